// `fxview bench`: frame times of an effect's techniques, printed as a table to compare with the
// thesis' FPS tables. Each frame is timed on the wall clock up to glFinish (the honest figure on
// every driver) and with a GL_TIME_ELAPSED query (meaningful on GPUs; on llvmpipe it only covers
// command submission, because rasterisation runs later in its threads).
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <thread>

#include "app/commands.hpp"
#include "app/gpu_cpu_compare.hpp"
#include "app/scene_options.hpp"
#include "context/context.hpp"
#include "core/error.hpp"
#include "gl/render_target.hpp"

namespace fxview::app {
namespace {

// llvmpipe, softpipe, swrast (OSMesa): the CPU draws the frame, outside the timer query.
bool is_software_renderer(const std::string& renderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer"})
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

std::string format_ms(double ms) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", ms);
    return text;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

std::vector<std::string> chosen_techniques(const RenderRequest& request, const std::vector<std::string>& listed) {
    if (!listed.empty()) return listed;
    return request.effect.technique.empty() ? technique_names(request.effect) : std::vector<std::string>{request.effect.technique};
}

// `--compare`: the wall time of a whole GPU-vs-CPU comparison per technique (context, effect, one
// frame, the CPU reference of every covered pixel on all cores), the median of `runs`.
int bench_compare(const RenderRequest& request, const std::vector<std::string>& listed, int runs, bool json) {
    const std::vector<std::string> techniques = chosen_techniques(request, listed);
    if (!json)
        std::printf("fxview compare, %dx%d, %s, %u hardware threads\n\n| technique | compare s (median of %d) | pixels | pass |\n"
                    "| --- | --- | --- | --- |\n",
                    request.width, request.height, request.effect.path.c_str(), std::thread::hardware_concurrency(), runs);
    for (const auto& technique : techniques) {
        std::vector<double> seconds;
        CompareResult result;
        for (int run = 0; run < runs; ++run) {
            const auto start = std::chrono::steady_clock::now();
            result = compare_technique(request, technique, {});
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        const double time = median(seconds);
        if (json)
            std::cout << nlohmann::json{{"technique", technique}, {"width", request.width}, {"height", request.height},
                                        {"compare_s_median", time}, {"runs", runs}, {"pixels", result.pixels}, {"pass", result.pass}}
                             .dump()
                      << "\n";
        else
            std::printf("| %s | %.2f | %ld | %s |\n", technique.c_str(), time, result.pixels,
                        !result.has_reference ? "no reference" : result.pass ? "yes" : "NO");
    }
    return 0;
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
    struct Options {
        SceneOptions scene;
        int frames = 10;
        bool json = false, compare = false;
        std::vector<std::string> techniques;
    };
    auto o = std::make_shared<Options>();
    o->scene.size = "1024x768";
    CLI::App* command = app.add_subcommand("bench", "Measure frame times of an effect's techniques (GPU timer queries)");
    add_scene_options(*command, o->scene);
    command->add_option("--frames", o->frames, "Measured frames per technique (after 2 warm-up frames)")->check(CLI::Range(1, 10000));
    command->add_flag("--json", o->json, "Print one JSON object per technique");
    command->add_option("--techniques", o->techniques,
                        "Techniques to measure, in this order (comma-separated); the speed-up column is relative to the first")
        ->delimiter(',');
    command->add_flag("--compare", o->compare,
                      "Time `fxview compare` of each technique instead (one GPU frame and its CPU reference on all cores), "
                      "at the size given (default 256x256 here)");
    return [o, command] {
        if (o->compare && command->get_option("--size")->count() == 0) o->scene.size = "256x256";
        const RenderRequest request = to_render_request(o->scene);
        if (request.effect.path.empty()) throw UsageError("bench needs an effect file");
        if (!o->techniques.empty() && !request.effect.technique.empty()) throw UsageError("bench: give --technique or --techniques, not both");
        if (o->compare) return bench_compare(request, o->techniques, o->frames, o->json);
        context::ContextOptions context_options;
        context_options.backend = request.backend;
        context_options.window_width = request.width;
        context_options.window_height = request.height;
        context_options.window_visible = false;
        const auto context = context::create_context(context_options);
        const auto info = context::query_context_info();
        const auto session = open_effect_session(request.effect);
        for (const std::string& warning : session->scene_warnings(request.scene))
            std::cerr << warning << "\n";
        const std::vector<std::string> techniques = chosen_techniques(request, o->techniques);
        double first_wall = 0;  // the speed-up's reference: the first technique's median
        gl::RenderTarget target({request.width, request.height, 1, request.samples});
        gl::Query query = gl::create_query(GL_TIME_ELAPSED);
        // A software rasteriser's timer covers command submission only: its figure would mislead.
        const bool timer_meaningful = !is_software_renderer(info.renderer);
        if (!o->json)
            std::printf("%s, %dx%d, %s\n\n| technique | wall ms (median) | FPS (wall) | GPU timer ms (median) | speed-up vs %s |\n"
                        "| --- | --- | --- | --- | --- |\n",
                        info.renderer.c_str(), request.width, request.height, request.effect.path.c_str(), techniques.front().c_str());
        for (const auto& technique : techniques) {
            session->select_technique(technique);
            std::vector<double> gpu_ms, wall_ms;
            for (int frame = 0; frame < o->frames + 2; ++frame) {
                const auto start = std::chrono::steady_clock::now();
                glBeginQuery(GL_TIME_ELAPSED, query.get());
                session->render(request.scene, target);
                glEndQuery(GL_TIME_ELAPSED);
                glFinish();
                const auto end = std::chrono::steady_clock::now();
                GLuint64 nanoseconds = 0;
                glGetQueryObjectui64v(query.get(), GL_QUERY_RESULT, &nanoseconds);
                if (frame < 2) continue;  // warm-up: shader compilation, texture residency
                gpu_ms.push_back(nanoseconds / 1e6);
                wall_ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
            }
            const double gpu = median(gpu_ms), wall = median(wall_ms);
            if (first_wall == 0) first_wall = wall;
            const double speed_up = wall > 0 ? first_wall / wall : 0.0;
            if (o->json)
                std::cout << nlohmann::json{{"technique", technique}, {"renderer", info.renderer}, {"width", request.width},
                                            {"height", request.height}, {"frames", o->frames},
                                            {"gpu_ms_median", timer_meaningful ? nlohmann::json(gpu) : nlohmann::json(nullptr)},
                                            {"wall_ms_median", wall}, {"fps_wall", wall > 0 ? 1000.0 / wall : 0.0},
                                            {"speed_up_vs_first", speed_up}}
                                 .dump()
                          << "\n";
            else
                std::printf("| %s | %.3f | %.2f | %s | %.1fx |\n", technique.c_str(), wall, wall > 0 ? 1000.0 / wall : 0.0,
                            timer_meaningful ? format_ms(gpu).c_str() : "n/a", speed_up);
        }
        if (!o->json && !timer_meaningful)
            std::printf("\nGPU timer n/a: %s rasterises in its own threads after the timer query ends; the wall time is the frame's cost.\n",
                        info.renderer.c_str());
        return 0;
    };
}

}  // namespace fxview::app
