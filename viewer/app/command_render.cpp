#include <filesystem>
#include <iostream>

#include "app/commands.hpp"
#include "app/offscreen_render.hpp"
#include "app/scene_options.hpp"
#include "image/image_file.hpp"

namespace fxview::app {

CommandRunner add_render_command(CLI::App& app) {
    struct Options {
        SceneOptions scene;
        std::string out = "out/render.png";
        bool no_srgb = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("render", "Render the scene headless to a PNG, EXR or PFM file");
    add_scene_options(*command, options->scene);
    command->add_option("--out,-o", options->out, "Output file: .png (8-bit), .exr or .pfm (32-bit float RGBA)")
        ->capture_default_str();
    command->add_flag("--no-srgb", options->no_srgb, "PNG: write linear values (legacy) instead of sRGB-encoded ones");
    return [options] {
        const RenderRequest request = to_render_request(options->scene);
        const auto parent = std::filesystem::path(options->out).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent);
        image::FloatImage image = render_offscreen(request);
        if (std::filesystem::path(options->out).extension() == ".png")  // 8-bit pictures: through the display transform
            image::apply_display_transform(image, request.display);
        image::write_image(options->out, image, options->no_srgb ? image::Encoding::Linear : image::Encoding::Srgb);
        std::cout << "wrote " << options->out << " (" << image.width << "x" << image.height << ")\n";
        return 0;
    };
}

}  // namespace fxview::app
