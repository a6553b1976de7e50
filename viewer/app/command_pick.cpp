#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "app/commands.hpp"
#include "app/offscreen_render.hpp"
#include "app/scene_options.hpp"
#include "app/value_parsing.hpp"
#include "image/pixel_info.hpp"

namespace fxview::app {

CommandRunner add_pick_command(CLI::App& app) {
    struct Options {
        SceneOptions scene;
        std::string at;
        bool json = false;
        bool no_srgb = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("pick", "Render the scene and report one pixel's exact value");
    add_scene_options(*command, options->scene);
    command->add_option("--at", options->at, "Pixel X,Y (origin top left)")->required();
    command->add_flag("--json", options->json, "Print one JSON object");
    command->add_flag("--no-srgb", options->no_srgb, "Report the 8-bit value without sRGB encoding (legacy)");
    return [options] {
        const RenderRequest request = to_render_request(options->scene);
        const glm::ivec2 at = parse_pixel("--at", options->at);
        const image::FloatImage image = render_offscreen(request);
        const auto encoding = options->no_srgb ? image::Encoding::Linear : image::Encoding::Srgb;
        const image::PixelInfo info = image::inspect_pixel(image, at.x, at.y, encoding);
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%08X", info.packed);
        if (options->json) {
            nlohmann::json out = {
                {"x", info.x},
                {"y", info.y},
                {"width", image.width},
                {"height", image.height},
                {"rgba", info.rgba},
                {"rgba8", info.rgba8},
                {"encoding", options->no_srgb ? "linear" : "srgb"},
                {"packed", info.packed},
                {"packed_hex", hex},
                {"normal", {info.normal.x, info.normal.y, info.normal.z}},
                {"covered", info.rgba[3] > 0.0f},  // false on the cleared background
            };
            std::cout << out.dump() << "\n";
        } else {
            std::printf("pixel (%d, %d)\n  float RGBA  %.9g %.9g %.9g %.9g\n  8-bit %s  %u %u %u %u\n"
                        "  packed      %u (%s)\n  normal      %.6f %.6f %.6f\n",
                        info.x, info.y, info.rgba[0], info.rgba[1], info.rgba[2], info.rgba[3],
                        options->no_srgb ? "linear" : "sRGB  ", info.rgba8[0], info.rgba8[1], info.rgba8[2],
                        info.rgba8[3], info.packed, hex, info.normal.x, info.normal.y, info.normal.z);
        }
        return 0;
    };
}

}  // namespace fxview::app
