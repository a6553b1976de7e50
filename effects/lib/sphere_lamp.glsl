// The thesis' lobes lit by a sphere lamp instead of a point: the lamp keeps the point's power (a white
// Lambertian surface facing it reflects the same), its radiance spread over its disc of angular radius
// α = asin(radius / distance). Each function returns what replaces the point light's factor, so that
// α → 0 gives back cos θ, (r·v)^p and (n·h)^p. CPU twin: viewer/reference/sphere_lamp.cpp.
#pragma once

// atan z − z to float precision for z ≥ 0: the lamp's diffuse factor divides it by sin²α, which would
// magnify the error of a driver's atan (llvmpipe's is ~1e-5) a hundredfold. The angle halved twice
// (tan(θ/2) = z / (1 + √(1 + z²))) leaves w < 0.42, whose series to w²⁵ is exact in float.
float atan_minus_argument(float z) {
    float w = z < 0.3 ? z : z / (1.0 + sqrt(1.0 + z * z));
    w = z < 0.3 ? w : w / (1.0 + sqrt(1.0 + w * w));
    float w2 = w * w, series = 0.0;
    for (int k = 12; k >= 1; --k) series = w2 * (1.0 / float(2 * k + 1) - series);  // Σ (−1)^(k+1) w^2k / (2k+1)
    // z < 0.3: atan z − z = −w·series; else atan z = 4 atan w.
    return z < 0.3 ? -w * series : 4.0 * (w - w * series) - z;
}

// cos θ for a point. For the sphere: its irradiance over the point's, E / (π sin²α), with E exact for
// a sphere cut by the horizon (Snyder 1996; Lagarde & de Rousiers 2014 write it
// E = (cos θ acos y − x s) sin²α + atan(s / x)): the point's cos θ while the whole disc is above the
// horizon. Divided by sin²α before it is evaluated, c acos y + s/x + (atan z − z)/sin²α with z = s/x,
// so that a small lamp's two nearly equal terms do not cancel in float.
float sphere_lamp_lambert(float cos_theta, float sin2_alpha) {
    if (cos_theta * cos_theta > sin2_alpha) return max(cos_theta, 0.0);
    float sin_theta = sqrt(max(1.0 - cos_theta * cos_theta, 1e-12));
    float x = sqrt(max(1.0 / sin2_alpha - 1.0, 1e-6)), y = clamp(-x * cos_theta / sin_theta, -1.0, 1.0);
    float s = sin_theta * sqrt(1.0 - y * y), z = s / x;
    return max(cos_theta * acos(y) + z + atan_minus_argument(z) / sin2_alpha, 0.0) / 3.14159265358979323846;
}

// Points on the disc: enough that neighbours lie within half the lobe's width (1/√p) of each other
// (sin α for α: a driver's asin is less exact than the count's steps need); 128 at least where the
// horizon crosses the disc (cos²θ < sin²α), whose cut 32 points would follow in steps of 3 %.
int sphere_lamp_points(float sin_alpha, float cos_theta, float power) {
    float fewest = cos_theta * cos_theta < sin_alpha * sin_alpha ? 128.0 : 32.0;
    return int(clamp(ceil(4.0 * 3.14159265358979323846 * sin_alpha * sin_alpha * power), fewest, 256.0));
}

// The lobes averaged over the lamp's disc around unit direction `l` (points of equal solid angle on a
// sunflower spiral; those below the horizon count 0), times Ω / (π sin²α), Ω = 2π(1 − cos α) the
// disc's solid angle: x Phong (r·v)^p, y Blinn (n·h)^p.
vec2 sphere_lamp_lobes(vec3 n, vec3 v, vec3 l, float sin_alpha, float power) {
    const float pi = 3.14159265358979323846, golden = pi * (3.0 - sqrt(5.0));
    // 1 - cos α as sin²α / (1 + cos α): exact in float for small lamps too.
    float cos_alpha = sqrt(max(1.0 - sin_alpha * sin_alpha, 0.0)), versine = sin_alpha * sin_alpha / (1.0 + cos_alpha);
    int count = sphere_lamp_points(sin_alpha, dot(n, l), power);
    float s = l.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (s + l.z), b = l.x * l.y * a;  // Duff et al.'s frame
    vec3 x = vec3(1.0 + s * l.x * l.x * a, s * b, -s * l.x), y = vec3(b, s + l.y * l.y * a, -l.y);
    vec2 sum = vec2(0.0);
    for (int j = 0; j < count; ++j) {
        float c = 1.0 - (float(j) + 0.5) / float(count) * versine, sine = sqrt(max(1.0 - c * c, 0.0)), phi = golden * float(j);
        vec3 d = c * l + sine * (cos(phi) * x + sin(phi) * y);
        if (dot(n, d) <= 0.0) continue;
        sum += vec2(pow(max(dot(reflect(-d, n), v), 0.0), power), pow(max(dot(n, normalize(d + v)), 0.0), power));
    }
    return sum / float(count) * (2.0 / (1.0 + cos_alpha));
}
