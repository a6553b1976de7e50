#include "app/scene_options.hpp"

#include <cmath>
#include <filesystem>

#include "app/effect_options.hpp"
#include "app/value_parsing.hpp"
#include "core/error.hpp"
#include "core/text.hpp"
#include "effect/preset.hpp"
#include "math/transform.hpp"

namespace fxview::app {

void add_scene_options(CLI::App& command, SceneOptions& o) {
    command.add_option("--mesh", o.mesh, "Built-in mesh (sphere, torus, cube, plane, disc, knot) or an .obj file")
        ->capture_default_str();
    command.add_option("--size", o.size, "Image size WIDTHxHEIGHT")->capture_default_str();
    command.add_option("--backend", o.backend, "GL context: egl (headless), egl-device (headless, EGL device platform only), osmesa (software) or glfw (window)")
        ->capture_default_str();
    command.add_option("--samples", o.samples_given, "MSAA samples (0 = off; default: the preset's, else 0)")->check(CLI::Range(0, 32));
    command.add_option("--debug-view", o.debug_view, "Debug shader: normals, uv, camera or light")->capture_default_str();
    command.add_option("--camera-distance", o.camera_distance, "Camera Z translation (zoom)")
        ->check(finite_range(0.01, 1000.0))
        ->capture_default_str();
    command.add_option("--camera-rotate", o.camera_rotate, "Camera rotation X,Y,Z in degrees (orbits the target)");
    command.add_option("--camera-pan", o.camera_pan, "Camera target X,Y");
    command.add_option("--fov", o.fov, "Vertical field of view in degrees")->check(finite_range(1.0, 179.0));
    command.add_option("--light-position", o.light_position, "Light position X,Y,Z")->capture_default_str();
    command.add_option("--light-rotate", o.light_rotate, "Light rotation about the origin X,Y,Z in degrees");
    command.add_option("--light-shape", o.light_shape,
                       "The light's shape: sphere (a point at radius 0), disc or rectangle (flat, facing the origin: a ceiling panel, a window)");
    auto* radius = command.add_option("--light-radius", o.light_radius, "Radius of a sphere or disc light (world units; 0: a point)")
                       ->check(finite_range(0.0, 1e3));
    auto* size = command.add_option("--light-size", o.light_size, "Width and height W,H of a rectangle light (world units)");
    command.add_option("--light-angle", o.light_angle,
                       "The light's angular radius seen from the origin, degrees (a rectangle: a square of this half-angle)")
        ->check(finite_range(0.0, 60.0))
        ->excludes(radius)
        ->excludes(size);
    command.add_option("--light-intensity", o.light_intensity,
                       "The light's intensity in photometric units: 500lx (illuminance at the origin), 800lm (flux), 120cd, "
                       "3000nit (luminance of its surface); scene radiance is then luminance in cd/m2 (pair it with --exposure). "
                       "Default: each effect's own light strength");
    command.add_option("--light-spectrum", o.light_spectrum,
                       "The light's spectrum, a name of the spectral library (`fxview spectra list`): every spectral effect's light "
                       "spectrum follows it (parameters annotated SceneLight = \"spectrum\")");
    command.add_option("--object-position", o.object_position, "Object position X,Y,Z");
    command.add_option("--object-rotate", o.object_rotate, "Object rotation X,Y,Z in degrees");
    command.add_option("--object-scale", o.object_scale, "Object scale X,Y,Z");
    command.add_option("--background", o.background, "Clear colour R,G,B,A (linear)");
    command.add_option("--environment", o.environment,
                       "Environment that lights image-based-lighting effects and fills the background: studio, sky[:ELEV[,CCT]], "
                       "furnace, none, an equirectangular .hdr/.exr, a cube cross, a cube .dds, or six face files F1,...,F6 (+X -X +Y -Y +Z -Z)");
    command.add_option("--environment-rotate", o.environment_rotate, "Environment rotation about the vertical axis, degrees");
    command.add_option("--environment-intensity", o.environment_intensity, "Environment radiance scale")->check(finite_range(0.0, 1e6));
    command.add_option("--exposure", o.exposure, "Exposure in EV stops for PNG output (factor 2^EV)")->check(finite_range(-30.0, 30.0));
    command.add_option("--tone-map", o.tone_map, "Tone mapper for PNG output: none, aces or pbr-neutral");
    command.add_flag("--gl-debug", o.gl_debug, "Print KHR_debug messages of the driver");
    add_effect_options(command, o.effect);
}

namespace {

// The light's shape and size from the options, else the preset's: a sphere (a point at radius 0), a
// disc of a radius, a rectangle of a size; --light-angle sizes any of them from the origin.
void set_light_shape(scene::Light& light, const SceneOptions& o, const effect::PresetScene& preset) {
    const std::string shape_name = o.light_shape.value_or(preset.light_shape.value_or("sphere"));
    const std::optional<scene::LightShape> shape = scene::parse_light_shape(shape_name);
    if (!shape) throw UsageError("--light-shape: '" + excerpt(shape_name) + "' is not sphere, disc or rectangle");
    light.shape = *shape;
    const float distance = glm::length(light.pose.position);
    // Farther, float shaders square the distance past their range (a black picture, not a dim one).
    if (!(distance <= 1e6f)) throw UsageError("--light-position: the light must lie within 1e6 world units of the origin");
    if (o.light_angle && *o.light_angle > 0 && distance == 0.0f)
        throw UsageError("--light-angle: the light sits at the origin; give --light-radius or --light-size instead");
    const double angle = glm::radians(o.light_angle.value_or(0.0f));
    // A sphere subtends asin(R / D), a disc or square facing the origin atan(R / D).
    const float reach = static_cast<float>(distance * (light.shape == scene::LightShape::Sphere ? std::sin(angle) : std::tan(angle)));
    light.radius = o.light_angle ? reach : o.light_radius.value_or(preset.light_radius.value_or(0.0f));
    if (o.light_size) {
        light.size = parse_vec2("--light-size", *o.light_size);
        if (!(light.size.x >= 0 && light.size.y >= 0 && light.size.x <= 1e3f && light.size.y <= 1e3f))
            throw UsageError("--light-size: width and height from 0 to 1000");
    } else if (o.light_angle) {
        light.size = glm::vec2(2.0f * reach);
    } else {
        light.size = preset.light_size.value_or(glm::vec2(0.0f));
    }
    if (o.light_size && light.shape != scene::LightShape::Rectangle) throw UsageError("--light-size: only a rectangle light has a width and height (--light-shape rectangle)");
    if (light.shape == scene::LightShape::Rectangle && o.light_radius) throw UsageError("--light-radius: a rectangle light is sized by --light-size W,H");
    // A preset's own shape and sizes are the preset's errors, at its lines.
    if (!o.light_size && !o.light_angle && preset.light_size && light.shape != scene::LightShape::Rectangle)
        throw Error(preset.where("light_size") + "only a rectangle light has a width and height (\"light_shape\": \"rectangle\")");
    if (light.shape != scene::LightShape::Sphere && !light.has_size()) {
        const std::string wanted = light.shape == scene::LightShape::Disc ? "radius" : "size";
        if (!o.light_shape && preset.light_shape)
            throw Error(preset.where("light_shape") + "a " + scene::light_shape_name(light.shape) + " light needs its " + wanted + " (\"light_" +
                        wanted + "\" above 0, or --light-" + wanted + " or --light-angle)");
        throw UsageError(std::string("--light-shape ") + scene::light_shape_name(light.shape) + ": give its size (" +
                         (light.shape == scene::LightShape::Disc ? "--light-radius R" : "--light-size W,H") + " or --light-angle DEG)");
    }
}

}  // namespace

RenderRequest to_render_request(const SceneOptions& o) {
    RenderRequest request;
    request.backend = context::parse_backend(o.backend);
    request.view = render::parse_debug_view(o.debug_view);
    const glm::ivec2 size = parse_size("--size", o.size);
    request.width = size.x;
    request.height = size.y;
    // The preset's scene settings, where the command line gives none.
    effect::PresetScene preset;
    if (!o.effect.preset.empty()) {
        // The preset may read what its effect may: the search roots, --allow-path, the effect's folder.
        effect::LoadOptions load = effect_load_options(o.effect.access);
        if (!o.effect.path.empty())
            load.access.allow_folder(std::filesystem::path(o.effect.path).parent_path().empty() ? std::filesystem::path(".")
                                                                                                  : std::filesystem::path(o.effect.path).parent_path());
        preset = effect::load_preset_scene(o.effect.preset, load.limits, load.access);
    }
    request.samples = o.samples_given.value_or(preset.samples.value_or(o.samples));
#ifndef NDEBUG
    request.gl_debug = true;  // debug builds always check GL errors
#else
    request.gl_debug = o.gl_debug;
#endif

    scene::Scene& scene = request.scene;
    scene.camera.pose.distance = o.camera_distance;
    scene.camera.pose.rotation = math::rotation_from_euler_degrees(parse_vec3("--camera-rotate", o.camera_rotate));
    scene.camera.pose.pan = parse_vec2("--camera-pan", o.camera_pan);
    scene.camera.fov_y_degrees = o.fov;
    scene.light.pose.position = parse_vec3("--light-position", o.light_position);
    scene.light.pose.rotation = math::rotation_from_euler_degrees(parse_vec3("--light-rotate", o.light_rotate));
    set_light_shape(scene.light, o, preset);
    scene.light.spectrum = o.light_spectrum.value_or(preset.light_spectrum.value_or(""));
    if (o.light_intensity) {
        scene.light.intensity = scene::parse_light_intensity(*o.light_intensity);
        if (!scene.light.intensity)
            throw UsageError("--light-intensity: '" + excerpt(*o.light_intensity) + "' is not a number (0 to 1e30) with a unit: lx, lm, cd or nit (e.g. 500lx)");
    } else if (preset.light_intensity) {
        scene.light.intensity = scene::parse_light_intensity(*preset.light_intensity);  // checked when the preset was read
    }
    if (scene.light.intensity) (void)scene::illuminance_at_origin(scene.light, *scene.light.intensity);  // a unit the light cannot have: said now
    scene::SceneObject& object = scene.objects.front();
    object.mesh = o.mesh;
    object.pose.position = parse_vec3("--object-position", o.object_position);
    object.pose.rotation = math::rotation_from_euler_degrees(parse_vec3("--object-rotate", o.object_rotate));
    object.scale = parse_vec3("--object-scale", o.object_scale);
    scene.background = parse_vec4("--background", o.background);
    const auto finite = [](const char* option, float value) {
        if (!std::isfinite(value)) throw UsageError(std::string(option) + ": not a finite number");
        return value;
    };
    const std::string environment = o.environment.value_or(preset.environment.value_or(""));
    scene.environment.source = environment == "none" ? "" : environment;
    scene.environment.rotation_degrees = finite("--environment-rotate", o.environment_rotate.value_or(preset.environment_rotate.value_or(0.0f)));
    scene.environment.intensity = finite("--environment-intensity", o.environment_intensity.value_or(preset.environment_intensity.value_or(1.0f)));
    if (scene.environment.intensity < 0.0f) throw UsageError("--environment-intensity: must be at least 0");
    request.display.exposure_ev = finite("--exposure", o.exposure.value_or(preset.exposure.value_or(0.0f)));
    if (std::abs(request.display.exposure_ev) > 30.0f) throw UsageError("--exposure: -30 to 30 EV");
    if (o.tone_map) request.display.tone_map = image::parse_tone_map(*o.tone_map);
    else if (preset.tone_map) {
        try {  // a bad name in the preset is the preset's error, at its line
            request.display.tone_map = image::parse_tone_map(*preset.tone_map);
        } catch (const UsageError& error) {
            throw Error(preset.where("tone_map") + error.what());
        }
    }
    if (scene.environment.source.size() > kMaxEnvironmentSourceChars) throw UsageError("--environment: longer than any list of six file names");
    request.effect = o.effect;
    // A preset names its effect: without one on the command line, that one (as written, next to the
    // preset, or in fxview's own folder, where the shipped presets' effects/... live), never the
    // debug view instead.
    if (request.effect.path.empty() && !preset.effect.empty()) {
        std::error_code error;
        for (const std::filesystem::path& candidate : {std::filesystem::path(preset.effect), std::filesystem::path(preset.path).parent_path() / preset.effect,
                                                       std::filesystem::path(spectra_folder()).parent_path() / preset.effect})
            if (request.effect.path.empty() && std::filesystem::is_regular_file(candidate, error)) request.effect.path = candidate.string();
        if (request.effect.path.empty())
            throw Error(preset.where("effect") + "the preset's effect '" + excerpt(preset.effect) + "' is not found (name the effect file before --preset)");
    }
    return request;
}

}  // namespace fxview::app
