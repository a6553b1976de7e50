// Any BRDF lit by the environment, by filtered importance sampling (Křivánek & Colbert 2008): 32
// directions, half cosine-distributed about n and half reflected about GGX normals of width `alpha`
// (the lobe's rough size), combined by the balance heuristic; each reads the prefiltered radiance
// whose lobe covers its share of the sphere, so the estimate is smooth. The disc lights in closed form.
// Included inside a fragment shader block after that block defines
// vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) (unit vectors as BRDF() takes them),
// below environment.glsl at the top level. No include guard: each block includes it once.
const int kFxEnvironmentSamples = 32;

// Sample i of the set and the mixture's density there.
vec3 environment_direction(vec3 n, vec3 v, vec3 x, vec3 y, int i, float alpha, out float pdf) {
    const float pi = 3.14159265358979323846;
    int k = i / 2;
    float u1 = (float(k) + 0.5) / float(kFxEnvironmentSamples / 2);
    float u2 = float(bitfieldReverse(uint(k))) * 2.3283064365386963e-10;
    vec3 l;
    if (i % 2 == 0) {
        float r = sqrt(u1), phi = 2.0 * pi * u2;
        l = r * cos(phi) * x + r * sin(phi) * y + sqrt(max(0.0, 1.0 - u1)) * n;
    } else {
        float cos_theta = sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
        float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta)), phi = 2.0 * pi * u2;
        vec3 h = sin_theta * cos(phi) * x + sin_theta * sin(phi) * y + cos_theta * n;
        l = 2.0 * dot(v, h) * h - v;
    }
    vec3 h = normalize(l + v);
    float nh = dot(n, h), a2 = alpha * alpha, d = nh * nh * (a2 - 1.0) + 1.0;
    pdf = 0.5 * max(dot(n, l), 0.0) / pi + 0.5 * a2 / (pi * d * d) * nh / (4.0 * max(dot(v, h), 1e-6));
    return l;
}

vec3 environment_light(vec3 n, vec3 v, vec3 x, vec3 y, float alpha) {
    if (FxEnvironmentIntensity <= 0.0) return vec3(0.0);
    if (dot(n, v) < 0.01) {  // a silhouette: the normal bent towards the eye, the frame with it
        n = environment_facing_normal(n, v);
        x = normalize(x - n * dot(n, x));
        y = cross(n, x);
    }
    vec3 sum = vec3(0.0);
    for (int i = 0; i < kFxEnvironmentSamples; ++i) {
        float pdf;
        vec3 l = environment_direction(n, v, x, y, i, alpha, pdf);
        float nl = dot(n, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;  // as Lit draws such a BRDF black
        sum += f * nl / pdf * environment_radiance(l, environment_share_roughness(1.0 / (float(kFxEnvironmentSamples) * pdf)));
    }
    // Each disc light through the BRDF at one point, the lobe's mean over the disc taken as that of a
    // GGX lobe of width alpha (environment_disc_alpha): the point nearest the mirror direction of the
    // disc shrunk by b²/α'² (b = radius/2): the disc itself for a mirror (its sharp image), the centre
    // for a lobe much wider than the disc.
    vec3 discs = vec3(0.0);
    vec3 r = reflect(-v, n);
    for (int k = 0; k < kFxEnvironmentDiscs; ++k) {
        vec3 centre;
        float radius;
        vec3 power = environment_disc(k, centre, radius);
        if (!(power.r + power.g + power.b > 0.0)) continue;
        float widened = environment_disc_alpha(alpha, radius), b = 0.5 * radius;
        vec3 l = environment_disc_nearest(centre, radius * b * b / (widened * widened), r);
        float nl = dot(n, l);
        if (nl <= 0.0) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;
        discs += f * nl * power * (alpha * alpha) / (widened * widened);
    }
    return sum / float(kFxEnvironmentSamples) + discs;
}
