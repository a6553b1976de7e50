// The scene light's size and shape: a sphere (`--light-radius`), or a flat disc or rectangle
// (`--light-shape`), a one-sided Lambertian emitter of uniform radiance that faces the origin and
// gives there the point light's irradiance. GPU twin of viewer/scene/light_geometry.cpp: the factors
// that replace the point light's cos θ, (r·v)^p and (n·h)^p (integrals over a flat light's solid
// angle), and the light's radiance along one direction (the CD's diffraction orders, the films'
// mirror image). Needs LightPosition (standard.glsl).
#pragma once

uniform float LightRadius : LIGHTRADIUS;     // a sphere's radius (0: a point); a flat light's equivalent
uniform float LightShape : LIGHTSHAPE;       // 0 a sphere or a point, 1 a disc, 2 a rectangle
uniform vec2 LightHalfSize : LIGHTHALFSIZE;  // half extents along the light's u and v
uniform mat3 LightFrame : LIGHTFRAME;        // columns u, v and the emitting side's normal
uniform float LightRadiance : LIGHTRADIANCE; // per unit intensity; 0: not a flat light

bool flat_light() { return LightShape > 0.5 && LightRadiance > 0.0; }
bool flat_light_is_disc() { return LightShape < 1.5; }
float flat_light_area() { return flat_light_is_disc() ? 3.14159265358979323846 * LightHalfSize.x * LightHalfSize.x : 4.0 * LightHalfSize.x * LightHalfSize.y; }

// The quadrature's point count: a Fibonacci number at least `wanted` and `fewest`, at most 233; its
// predecessor is the rectangle's lattice step.
ivec2 flat_light_count(float wanted) {
    const int fibonacci[6] = int[6](21, 34, 55, 89, 144, 233);
    for (int i = 1; i < 6; ++i)
        if (float(fibonacci[i]) >= wanted) return ivec2(fibonacci[i], fibonacci[i - 1]);
    return ivec2(233, 144);
}

// Point j of `count` of equal area: a disc's sunflower spiral, a rectangle's Fibonacci lattice (exact in integers).
vec3 flat_light_point(int j, ivec2 count) {
    vec2 q;
    if (flat_light_is_disc()) {
        float r = sqrt((float(j) + 0.5) / float(count.x)), phi = 3.14159265358979323846 * (3.0 - sqrt(5.0)) * float(j);
        q = LightHalfSize.x * r * vec2(cos(phi), sin(phi));
    } else {
        q = LightHalfSize * (2.0 * vec2((float(j) + 0.5) / float(count.x), (float((j * count.y) % count.x) + 0.5) / float(count.x)) - 1.0);
    }
    return LightPosition + q.x * LightFrame[0] + q.y * LightFrame[1];
}

// ∫ L max(cos θ, 0) dω, ∫ L (r·v)^p dω and ∫ L (n·h)^p dω over the light (those of a point light are
// cos θ and the two lobes), by the light's points: 4 Ω p of them (Ω its solid angle) so that
// neighbours lie within the lobe's width, 144 at least where the horizon crosses it, 34 else.
vec3 flat_light_factors(vec3 position, vec3 n, vec3 v, float power, bool lobes) {
    vec3 to_centre = LightPosition - position;
    float distance2 = max(dot(to_centre, to_centre), 1e-12);
    vec3 l = to_centre * inversesqrt(distance2);
    float area = flat_light_area(), solid = min(area * max(-dot(l, LightFrame[2]), 0.0) / distance2, 6.2831853);
    float cos_theta = dot(n, l);
    ivec2 count = flat_light_count(max(ceil(4.0 * solid * (lobes ? power : 1.0)), cos_theta * cos_theta < solid / 3.14159265 ? 144.0 : 34.0));
    vec3 sum = vec3(0.0);
    for (int j = 0; j < count.x; ++j) {
        vec3 d = flat_light_point(j, count) - position;
        float r2 = dot(d, d);
        vec3 dir = d * inversesqrt(r2);
        float emitted = -dot(dir, LightFrame[2]), cosine = dot(n, dir);
        if (emitted <= 0.0 || cosine <= 0.0) continue;
        float w = emitted / r2;
        sum.x += w * cosine;
        if (lobes) sum.yz += w * vec2(pow(max(dot(reflect(-dir, n), v), 0.0), power), pow(max(dot(n, normalize(dir + v)), 0.0), power));
    }
    return sum * (LightRadiance * area / float(count.x));
}

// ∫ over the outline offset inwards by 0..x and outwards by 0..y (layer-cake form of the edge ramp's integral).
float flat_light_offset_integral(vec2 h, float x, float y, bool disc) {
    float product = h.x * h.y, sum = h.x + h.y, pi = 3.14159265358979323846;
    float inner = product * x - sum * x * x / 2.0 + x * x * x / 3.0;
    if (disc) return pi * (inner + product * y + sum * y * y / 2.0 + y * y * y / 3.0);
    return 4.0 * inner + 4.0 * product * y + 2.0 * sum * y * y + pi * y * y * y / 3.0;
}

// The flat light seen from one surface point: what every lookup from there shares.
struct FlatLightView {
    vec3 position;
    float height;       // above the light's plane, on its emitting side (<= 0: behind it)
    vec2 below;         // the point's in-plane coordinates
    vec2 half_angles;   // the light's angular half extents seen from there (a disc: its ellipse's)
    float sharp;        // the light's angular area: π h1 h2 or 4 h1 h2
};

FlatLightView flat_light_view(vec3 position) {
    FlatLightView f;
    vec3 from_centre = position - LightPosition, n = LightFrame[2];
    f.position = position;
    f.height = dot(from_centre, n);
    f.below = vec2(dot(from_centre, LightFrame[0]), dot(from_centre, LightFrame[1]));
    float distance = length(from_centre);
    vec3 l = -from_centre / distance;
    vec2 along = vec2(dot(l, LightFrame[0]), dot(l, LightFrame[1]));
    f.half_angles = flat_light_is_disc() ? vec2(LightHalfSize.x, LightHalfSize.x * max(-dot(l, n), 0.0)) / distance
                                         : LightHalfSize * sqrt(max(vec2(1.0) - along * along, 0.0)) / distance;
    f.sharp = (flat_light_is_disc() ? 3.14159265358979323846 : 4.0) * f.half_angles.x * f.half_angles.y;
    return f;
}

// The angle (a chord between unit directions) from unit `direction` to the nearest point of the
// light's outline, seen from the view's point: positive inside, -1e30 where the ray misses the
// light's emitting side. `disc`: flat_light_is_disc(), passed as a constant where a loop calls this
// (llvmpipe runs both sides of a branch in a loop).
float flat_light_angle(FlatLightView f, vec3 direction, bool disc) {
    vec3 local = direction * LightFrame;  // the direction in the light's frame: across, up, out of its face
    if (local.z >= 0.0 || f.height <= 0.0) return -1e30;
    vec2 q = f.below - (f.height / local.z) * local.xy;  // where the ray meets the light's plane
    vec2 outline;  // the outline's point nearest q
    float inside;
    if (disc) {
        float r = length(q);
        inside = LightHalfSize.x - r;
        outline = r > 0.0 ? q * (LightHalfSize.x / r) : vec2(LightHalfSize.x, 0.0);
    } else {
        vec2 beyond = abs(q) - LightHalfSize;
        float most = max(beyond.x, beyond.y);
        vec2 snapped = vec2(q.x < 0.0 ? -LightHalfSize.x : LightHalfSize.x, q.y < 0.0 ? -LightHalfSize.y : LightHalfSize.y);
        // Outside: the rectangle's nearest point; inside: q moved to the nearer side. Selects rather
        // than branches: llvmpipe runs every side of a branch, and this runs per order and band.
        outline = most > 0.0 ? clamp(q, -LightHalfSize, LightHalfSize) : (beyond.x > beyond.y ? vec2(snapped.x, q.y) : vec2(q.x, snapped.y));
        inside = most > 0.0 ? -length(max(beyond, vec2(0.0))) : -most;
    }
    // As the chord between unit directions (the in-plane distance over t would vanish for rays that
    // graze the light's plane).
    return sign(inside) * length(local - normalize(vec3(outline - f.below, -f.height)));
}

// A lower bound on the height along unit `normal` of the directions from the view's point to the light:
// the least over its corners (a disc's: its square's). The directions to a flat convex light form a
// convex spherical polygon; where its corners lie above the plane of `normal`, so does all of it, and a
// height along a great-circle arc inside that hemisphere is least at the arc's ends. (A corner below
// the plane makes the bound negative: it then bounds nothing.)
float flat_light_lowest_height(FlatLightView f, vec3 normal, bool disc) {
    vec3 u = LightFrame[0] * LightHalfSize.x, w = LightFrame[1] * (disc ? LightHalfSize.x : LightHalfSize.y), c = LightPosition - f.position;
    return min(min(dot(normalize(c + u + w), normal), dot(normalize(c + u - w), normal)),
               min(dot(normalize(c - u + w), normal), dot(normalize(c - u - w), normal)));
}

// The radiance inside the light's image blurred by an angle `width` (the outline ramped linearly over
// `width`), divided by the light the ramp adds so that the blurred light keeps its energy.
float flat_light_ramp_scale(FlatLightView f, float width, bool disc) {
    float ramped = flat_light_offset_integral(f.half_angles, min(0.5 * width, min(f.half_angles.x, f.half_angles.y)), 0.5 * width, disc) / width;
    return ramped > 0.0 ? LightRadiance * f.sharp / ramped : 0.0;
}

// The light's radiance along unit `direction` from the view's point, its image blurred by `width`.
float flat_light_radiance(FlatLightView f, vec3 direction, float width, bool disc) {
    float angle = flat_light_angle(f, direction, disc);
    if (width <= 0.0) return angle >= 0.0 ? LightRadiance : 0.0;
    float ramp = clamp(0.5 + angle / width, 0.0, 1.0);
    return ramp > 0.0 ? ramp * flat_light_ramp_scale(f, width, disc) : 0.0;
}

// The sphere light (cd.fx's orders, the films' mirror image) measured in chords (no inverse
// trigonometry: its GPU approximations shift a sharp edge visibly), as viewer/optics/grating_orders.hpp: the edge's chord 2 sin(α/2) from sin α, and the
// radiance at chord c from the centre of a light of unit irradiance at normal incidence, its image
// softened by a ramp of width w around the edge and divided by the ramp's exact irradiance.
float light_edge_chord(float sin_alpha) {
    float s = clamp(sin_alpha, 0.0, 1.0);
    return s * sqrt(2.0 / (1.0 + sqrt(1.0 - s * s)));
}

// Inside the light's image (where the ramp is 1): 1 / (2π ∫ p(c) cos δ c dc).
float sphere_light_ramp_scale(float edge, float width) {
    float a = edge - 0.5 * width, b = edge + 0.5 * width;
    float moment = a >= 0.0 ? a * a / 2.0 - a * a * a * a / 8.0 +
                                  width * (a / 2.0 + width / 6.0 - a * a * a / 4.0 - a * a * width / 4.0 - a * width * width / 8.0 -
                                           width * width * width / 40.0)
                            : (b * b * b / 6.0 - b * b * b * b * b / 40.0) / width;
    return moment > 0.0 ? 1.0 / (2.0 * 3.14159265358979323846 * moment) : 0.0;
}

float sphere_light_radiance(float chord, float edge, float width) {
    float b = edge + 0.5 * width;
    if (chord >= b) return 0.0;
    return clamp((b - chord) / width, 0.0, 1.0) * sphere_light_ramp_scale(edge, width);
}


// The scene light's radiance (per unit of the effect's light strength) along unit `direction` from
// `position`, its image blurred by an angle `width`: a sphere's disc, a flat light's outline; 0 for a
// point, which has no image.
float scene_light_radiance(vec3 position, vec3 direction, float width) {
    if (flat_light()) return flat_light_radiance(flat_light_view(position), direction, width, flat_light_is_disc());
    if (!(LightRadius > 0.0)) return 0.0;
    vec3 to_light = LightPosition - position;
    float distance = length(to_light);
    return sphere_light_radiance(length(direction - to_light / distance), light_edge_chord(LightRadius / distance), max(width, 1e-6));
}
