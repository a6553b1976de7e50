// Analytic BRDFs (DOMAIN.md §7): microfacet terms and the models of effects/brdf/analytic.fx, each
// returning f(l, v) per RGB channel. The CPU references are viewer/brdf/models.cpp.
#pragma once

const float kPi = 3.14159265359;

struct Frame { vec3 n, l, v, t; float nl, nv, nh, vh; vec3 h; };

// World-space frame at a fragment: the tangent made orthogonal to n (any perpendicular where the
// mesh's tangent is parallel to n).
Frame make_frame(vec3 position, vec3 normal, vec3 tangent, vec3 light_position, vec3 camera_position) {
    Frame f;
    f.n = normalize(normal);
    f.l = normalize(light_position - position);
    f.v = normalize(camera_position - position);
    vec3 t = tangent - f.n * dot(f.n, tangent);
    if (dot(t, t) < 1e-12) t = cross(f.n, abs(f.n.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0));
    f.t = normalize(t);
    f.h = normalize(f.l + f.v);
    f.nl = dot(f.n, f.l);
    f.nv = dot(f.n, f.v);
    f.nh = dot(f.n, f.h);
    f.vh = dot(f.v, f.h);
    return f;
}

// The frame of unit vectors to the light and the eye, the normal and the tangent (orthogonal to n).
Frame frame_of(vec3 l, vec3 v, vec3 n, vec3 t) {
    Frame f;
    f.n = n;
    f.l = l;
    f.v = v;
    f.t = t;
    f.h = normalize(l + v);
    f.nl = dot(n, l);
    f.nv = dot(n, v);
    f.nh = dot(n, f.h);
    f.vh = dot(v, f.h);
    return f;
}

bool visible(Frame f) { return f.nl > 0.0 && f.nv > 0.0; }

float ggx(float nh, float alpha) {
    float a2 = alpha * alpha;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}
float beckmann(float nh, float m, bool printed) {
    float cos2 = nh * nh;
    float tan2 = (1.0 - cos2) / cos2;
    return exp(-tan2 / (m * m)) / ((printed ? 4.0 : kPi) * m * m * cos2 * cos2);
}
float schlick_ggx(float x, float roughness) {
    float k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    return x / (x * (1.0 - k) + k);
}
float v_cavity(Frame f) { return min(1.0, min(2.0 * f.nh * f.nv / f.vh, 2.0 * f.nh * f.nl / f.vh)); }
// c clamped: a float v·h of a light beside the eye reaches 1.0000001, and GLSL's pow of a negative
// base is undefined (NaN on llvmpipe: brdf-check found it at θi 1°).
vec3 fresnel_schlick(vec3 f0, float c) { return f0 + (1.0 - f0) * pow(clamp(1.0 - c, 0.0, 1.0), 5.0); }
float fresnel_full(float eta, float c) {
    float g2 = eta * eta + c * c - 1.0;
    if (g2 < 0.0) return 1.0;
    float g = sqrt(g2);
    float a = (g - c) / (g + c), b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    return 0.5 * a * a * (1.0 + b * b);
}

vec3 metallic_roughness(Frame f, vec3 base, float metallic, float roughness) {
    vec3 F = fresnel_schlick(mix(vec3(0.04), base, metallic), max(f.vh, 0.0));
    float dg = ggx(f.nh, roughness * roughness) * schlick_ggx(f.nv, roughness) * schlick_ggx(f.nl, roughness);
    return (1.0 - F) * (1.0 - metallic) * base / kPi + dg * F / (4.0 * f.nl * f.nv);
}
vec3 modified_phong(Frame f, vec3 kd, float ks, float n) {
    float rv = max(dot(reflect(-f.l, f.n), f.v), 0.0);
    return kd / kPi + ks * (n + 2.0) / (2.0 * kPi) * pow(rv, n);
}
vec3 cook_torrance_beckmann(Frame f, vec3 kd, float ks, float m, float eta, bool printed) {
    return kd / kPi + ks * beckmann(f.nh, m, printed) * v_cavity(f) * fresnel_full(eta, f.vh) / (4.0 * f.nl * f.nv);
}
vec3 ashikhmin_shirley(Frame f, vec3 rd, vec3 rs, float nu, float nv) {
    vec3 diffuse = 28.0 / (23.0 * kPi) * rd * (1.0 - rs) * (1.0 - pow(1.0 - f.nl / 2.0, 5.0)) * (1.0 - pow(1.0 - f.nv / 2.0, 5.0));
    float hu = dot(f.h, f.t), hv = dot(f.h, cross(f.n, f.t));
    float tangential = hu * hu + hv * hv;
    // h along n: the azimuth is undefined, and so is the exponent (0/0; a float denormal may pass a
    // test against 0): the mean of the two.
    float exponent = tangential > 1e-20 ? (nu * hu * hu + nv * hv * hv) / tangential : 0.5 * (nu + nv);
    float lobe = sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * kPi) * pow(f.nh, exponent) / (f.vh * max(f.nl, f.nv));
    return diffuse + lobe * fresnel_schlick(rs, f.vh);
}
vec3 ashikhmin_shirley_fit(Frame f, vec3 cd, vec3 cs, float ns) {
    return cd / kPi + (ns + 1.0) / (8.0 * kPi) * pow(f.nh, ns) / (f.vh * max(f.nl, f.nv)) * cs;
}
// The further models the fitter offers (viewer/fit/fit_models.cpp), Schlick's F0 per channel.
float smith_ggx_correlated(float nl, float nv, float alpha) {
    float a2 = alpha * alpha;
    float lambda_l = 0.5 * (sqrt(1.0 + a2 * (1.0 - nl * nl) / (nl * nl)) - 1.0);
    float lambda_v = 0.5 * (sqrt(1.0 + a2 * (1.0 - nv * nv) / (nv * nv)) - 1.0);
    return 1.0 / (1.0 + lambda_l + lambda_v);
}
vec3 cook_torrance_ggx(Frame f, vec3 kd, vec3 f0, float alpha) {
    float dg = ggx(f.nh, alpha) * smith_ggx_correlated(f.nl, f.nv, alpha);
    return kd / kPi + dg / (4.0 * f.nl * f.nv) * fresnel_schlick(f0, max(f.vh, 0.0));
}
vec3 cook_torrance_beckmann_schlick(Frame f, vec3 kd, vec3 f0, float m) {
    float dg = beckmann(f.nh, m, false) * v_cavity(f);
    return kd / kPi + dg / (4.0 * f.nl * f.nv) * fresnel_schlick(f0, max(f.vh, 0.0));
}
vec3 blinn_phong(Frame f, vec3 kd, vec3 ks, float n) {
    return kd / kPi + ks * (n + 8.0) / (8.0 * kPi) * pow(max(f.nh, 0.0), n);
}
vec3 ward_isotropic(Frame f, vec3 kd, vec3 ks, float alpha) {
    float a2 = alpha * alpha, cos2 = f.nh * f.nh;
    float tan2 = (1.0 - cos2) / cos2;
    return kd / kPi + ks * exp(-tan2 / a2) / (4.0 * kPi * a2 * sqrt(f.nl * f.nv));
}
