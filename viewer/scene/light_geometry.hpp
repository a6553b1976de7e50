// The scene light's shape in world space, in double precision: what effects read through the light
// semantics (LIGHTSHAPE, LIGHTHALFSIZE, LIGHTFRAME, LIGHTRADIANCE) and CPU references integrate.
//   sphere     a point (radius 0) or a ball of `radius`: the lamp of effects/lib/sphere_lamp.glsl,
//              which keeps the point light's irradiance at every surface point
//   disc       a flat round emitter of `radius` (a ceiling panel, a round window)
//   rectangle  a flat emitter `width` x `height` (a window, a softbox)
// Flat lights face the origin (their emitting side's normal points at it) and emit a uniform
// radiance, one-sided and Lambertian: the intensity sets the irradiance they give at the origin on a
// surface facing them (1: that of the unit point light), so surfaces nearer to them get more and
// surfaces they see at a grazing angle less, as under a real panel. effects/lib/area_light.glsl is
// the GPU twin.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace fxview::scene {

struct Light;
enum class LightShape { Sphere, Disc, Rectangle };

std::optional<LightShape> parse_light_shape(std::string_view name);  // "sphere" ("point"), "disc", "rectangle"
const char* light_shape_name(LightShape shape);

struct LightGeometry {
    LightShape shape = LightShape::Sphere;
    glm::dvec3 centre{0.0};
    double radius = 0;            // sphere, disc; 0 with a sphere: a point
    glm::dvec2 half_size{0.0};    // flat lights: half extents along u and v (a disc: its radius twice)
    glm::dvec3 u{1, 0, 0}, v{0, 1, 0}, normal{0, 0, 1};  // flat lights: in-plane axes, emitting side (towards the origin)
    double radiance = 0;          // flat lights: radiance per unit intensity; 0: none (a sphere; a flat light of under 1e-12 sr seen from the origin, a point)

    bool is_flat() const { return shape != LightShape::Sphere && radiance > 0; }
    double area() const;  // flat lights
    // The radius effects that know only LIGHTRADIUS see: a sphere's, a disc's, a rectangle's of equal area.
    double equivalent_radius() const;
    // The flat light's outline in world space (`segments` points of a disc; a rectangle's 4 corners).
    std::vector<glm::dvec3> outline(int segments = 48) const;
};

LightGeometry light_geometry(const Light& light);

// Irradiance on a surface at the origin facing a flat light of unit radiance (the light's own axis
// passes through the origin): a disc π R²/(R² + D²), a rectangle by the closed form for a point on a
// rectangle's axis (four corner rectangles, each (1/2)[a/√(a²+D²) atan(b/√(a²+D²)) + b/√(b²+D²) atan(a/√(b²+D²))]).
double flat_light_irradiance_at_origin(LightShape shape, glm::dvec2 half_size, double distance);

// Where a ray from `position` along unit `direction` meets a flat light: the angle (radians, small-angle)
// from the hit to the outline, positive inside, and the light's angular half extents seen from
// `position` (for the edge ramp's normalisation). Empty: the ray misses the emitting side's plane.
struct FlatLightHit {
    double inside_angle = 0;
    glm::dvec2 angular_half_size{0.0};
};
std::optional<FlatLightHit> flat_light_hit(const LightGeometry& light, const glm::dvec3& position, const glm::dvec3& direction);
glm::dvec2 flat_light_angular_half_size(const LightGeometry& light, const glm::dvec3& position);

// The flat light's radiance (per unit intensity) along a direction whose image is blurred by an
// angle `width`: the edge ramped linearly over `width` about the outline, divided by how much light the
// ramp adds (so that the blurred light holds the sharp light's energy): cd.fx's orders.
double flat_light_radiance(const LightGeometry& light, const glm::dvec3& position, const glm::dvec3& direction, double width);
// The same where the ramp is 1 (inside the image), for a light seen with `angular_half_size`.
double flat_light_ramp_scale(const LightGeometry& light, glm::dvec2 angular_half_size, double width);

// The quadrature the GPU uses over a flat light: `count` points of equal area (a disc: a sunflower
// spiral; a rectangle: the Fibonacci lattice), count a Fibonacci number from 34 to 233.
int flat_light_point_count(double wanted, double fewest);
glm::dvec3 flat_light_point(const LightGeometry& light, int j, int count);

}  // namespace fxview::scene
