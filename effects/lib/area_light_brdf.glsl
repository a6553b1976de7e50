// Any BRDF lit by the scene light as what it is: a point, a sphere or a flat disc or rectangle
// (area_light.glsl). For a sized light the reflected radiance ∫ f(l, v) cos θ L dω over the light is
// estimated from two deterministic sets of directions, combined by the balance heuristic (Veach 1997):
// points spread evenly over the light (a sphere's disc in rings of equal solid angle, a flat light in equal
// areas: good where the lobe is wider than the light) and directions reflected about GGX normals of
// the lobe's rough width `alpha` (good where the light is wider than the lobe: a sharp highlight of a
// large window). Each direction counts f cos θ L / (N_light p_light + N_lobe p_lobe), so that neither
// set's misses cost noise; the lobe's set counts fully only where the light is larger than the lobe. A sphere keeps the point light's irradiance at normal incidence (its
// radiance E / (π sin²α)), a flat light its own radiance (it falls off with distance as a real panel).
// Included inside a fragment shader block after that block defines
// vec3 fx_environment_brdf(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y), below area_light.glsl at the top
// level. No include guard: each block includes it once. CPU twin: viewer/reference/area_light_brdf.cpp.
const int kFxLightLobeSamples = 64;
const int kFxLightCosineSamples = 128;

// The density of GGX-reflected directions of width alpha about n for the eye v, per solid angle of l.
float light_lobe_pdf(vec3 n, vec3 v, vec3 l, float alpha) {
    vec3 h = normalize(l + v);
    float nh = dot(n, h), vh = dot(v, h);
    if (nh <= 0.0 || vh <= 0.0) return 0.0;
    float a2 = alpha * alpha, d = nh * nh * (a2 - 1.0) + 1.0;
    return a2 / (3.14159265358979323846 * d * d) * nh / (4.0 * vh);
}

// Direction i of the lobe's set: the GGX normal at the Hammersley point (i + ½)/N, radical inverse of i.
vec3 light_lobe_direction(vec3 n, vec3 v, vec3 x, vec3 y, int i, float alpha) {
    float u1 = (float(i) + 0.5) / float(kFxLightLobeSamples), u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
    float cos_theta = sqrt((1.0 - u1) / (1.0 + (alpha * alpha - 1.0) * u1));
    float sin_theta = sqrt(max(0.0, 1.0 - cos_theta * cos_theta)), phi = 2.0 * 3.14159265358979323846 * u2;
    vec3 h = sin_theta * cos(phi) * x + sin_theta * sin(phi) * y + cos_theta * n;
    return 2.0 * dot(v, h) * h - v;
}

// The scene light as the balance heuristic needs it, seen from one point.
struct LightSampling {
    bool flat_light;
    vec3 position, centre;  // centre: the unit direction to a sphere's centre
    float cos_alpha;        // a sphere's angular radius α
    float versine;          // 1 − cos α
    float radiance;         // per unit of the effect's light strength
    float solid_density;    // a sphere: 1 / Ω
    float solid;            // Ω, the light's solid angle
    float nearness;         // a flat light's area over the squared distance to its nearest point (capped at 2π)
    ivec2 count;            // the light's points and the rectangle lattice's step (flat_light_count)
};

LightSampling light_sampling(vec3 position, vec3 n) {
    LightSampling s;
    s.flat_light = flat_light();
    s.position = position;
    vec3 to_light = LightPosition - position;
    float distance2 = max(dot(to_light, to_light), 1e-12);
    s.centre = to_light * inversesqrt(distance2);
    float solid;
    if (s.flat_light) {
        s.radiance = LightRadiance;
        solid = min(flat_light_area() * max(-dot(s.centre, LightFrame[2]), 0.0) / distance2, 6.2831853);
        s.cos_alpha = s.versine = 0.0;
        s.solid_density = 0.0;
    } else {
        float sin2 = min(LightRadius * LightRadius / distance2, 0.9998);  // a lamp that reaches the point: 89°
        s.cos_alpha = sqrt(1.0 - sin2);
        s.versine = sin2 / (1.0 + s.cos_alpha);  // exact in float for small lamps too
        solid = 2.0 * 3.14159265358979323846 * s.versine;
        s.radiance = 1.0 / (3.14159265358979323846 * sin2);
        s.solid_density = 1.0 / solid;
    }
    s.solid = solid;
    s.nearness = solid;
    if (s.flat_light) {  // seen edge-on from close by, a panel subtends little but its points lie near
        vec3 from_centre = position - LightPosition;
        vec2 below = vec2(dot(from_centre, LightFrame[0]), dot(from_centre, LightFrame[1]));
        float outside = flat_light_is_disc() ? max(length(below) - LightHalfSize.x, 0.0) : length(max(abs(below) - LightHalfSize, 0.0));
        float height = dot(from_centre, LightFrame[2]);
        s.nearness = min(flat_light_area() / max(height * height + outside * outside, 1e-12), 6.2831853);
    }
    // 89 points (34 left 1-1.5 % errors on a Lambertian surface), 144 where the horizon crosses the
    // light, 233 where the light is near (its points' 1 / r² varies fast).
    float cos_theta = dot(n, s.centre);
    s.count = flat_light_count(s.nearness > 1.5 ? 233.0 : cos_theta * cos_theta < solid / 3.14159265 ? 144.0 : 89.0);
    if (!s.flat_light) s.count.x = s.count.x / 2 * 2;  // a sphere's points come in opposite pairs
    return s;
}

// Point j of the light as a unit direction, and its density per solid angle.
vec3 light_sample(LightSampling s, int j, out float pdf) {
    if (s.flat_light) {
        vec3 d = flat_light_point(j, s.count) - s.position;
        float r2 = dot(d, d);
        vec3 dir = d * inversesqrt(r2);
        float emitted = -dot(dir, LightFrame[2]);
        pdf = emitted > 0.0 ? r2 / (flat_light_area() * emitted) : 0.0;
        return dir;
    }
    const float golden = 3.14159265358979323846 * (3.0 - sqrt(5.0));
    vec3 l = s.centre;
    float sgn = l.z >= 0.0 ? 1.0 : -1.0, a = -1.0 / (sgn + l.z), b = l.x * l.y * a;  // Duff et al.'s frame
    vec3 x = vec3(1.0 + sgn * l.x * l.x * a, sgn * b, -sgn * l.x), y = vec3(b, sgn + l.y * l.y * a, -l.y);
    // Rings of equal solid angle, each with two opposite points (golden-angle turns between rings), so
    // that an integrand linear in the direction (a Lambertian surface's cos θ) sums exactly.
    int ring = j / 2;
    float c = 1.0 - (float(ring) + 0.5) / float(s.count.x / 2) * s.versine, sine = sqrt(max(1.0 - c * c, 0.0));
    float phi = golden * float(ring) + (j % 2 == 1 ? 3.14159265358979323846 : 0.0);
    pdf = s.solid_density;
    return c * l + sine * (cos(phi) * x + sin(phi) * y);
}

// The light's density per solid angle along unit `dir` (0: the direction misses it).
float light_pdf_along(LightSampling s, vec3 dir) {
    if (!s.flat_light) return dot(dir, s.centre) >= s.cos_alpha ? s.solid_density : 0.0;
    float towards = -dot(dir, LightFrame[2]);
    vec3 from_centre = s.position - LightPosition;
    float height = dot(from_centre, LightFrame[2]);
    if (towards <= 0.0 || height <= 0.0) return 0.0;
    float t = height / towards;
    vec2 q = vec2(dot(from_centre, LightFrame[0]), dot(from_centre, LightFrame[1])) + t * vec2(dot(dir, LightFrame[0]), dot(dir, LightFrame[1]));
    bool inside = flat_light_is_disc() ? dot(q, q) <= LightHalfSize.x * LightHalfSize.x : all(lessThanEqual(abs(q), LightHalfSize));
    return inside ? t * t / (flat_light_area() * towards) : 0.0;
}

bool scene_light_sized() { return flat_light() || LightRadius > 0.0; }

// Direction i of the cosine-distributed set about n (Hammersley), its density n·l / π.
vec3 light_cosine_direction(vec3 n, vec3 x, vec3 y, int i) {
    float u1 = (float(i) + 0.5) / float(kFxLightCosineSamples), u2 = float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10;
    float r = sqrt(u1), phi = 2.0 * 3.14159265358979323846 * u2;
    return r * cos(phi) * x + r * sin(phi) * y + sqrt(max(0.0, 1.0 - u1)) * n;
}

// The BRDF's own lobe width about the mirror direction, as a GGX width: where f falls to half its
// mirror value (tilting across the plane of incidence in steps of √3 from 0.002 rad), over 1.3 (a
// GGX lobe of width α falls to half about 1.3 α from its peak in the reflected direction); 1 where it
// does not fall by half within 0.55 rad (a broad or diffuse BRDF), `fallback` where the mirror
// direction is near the horizon or f vanishes there. For BRDFs whose lobe is not known in advance.
float brdf_lobe_width(vec3 n, vec3 v, vec3 x, vec3 y, float fallback) {
    vec3 r = reflect(-v, n);
    if (dot(n, r) < 0.05) return fallback;
    vec3 across = cross(n, r);
    across = dot(across, across) > 1e-8 ? normalize(across) : x;
    float peak = dot(fx_environment_brdf(r, v, n, x, y), vec3(0.2126, 0.7152, 0.0722));
    if (!(peak > 0.0) || isinf(peak)) return fallback;
    float width = 0.002;
    for (int k = 0; k < 11; ++k, width *= 1.7320508) {
        vec3 tilted = cos(width) * r + sin(width) * across;
        if (dot(n, tilted) <= 0.0) break;
        if (dot(fx_environment_brdf(tilted, v, n, x, y), vec3(0.2126, 0.7152, 0.0722)) < 0.5 * peak) return width / 1.3;
    }
    return 1.0;
}

// ∫ f(l, v) cos θ L dω over the scene light per unit of the effect's light strength (a point light:
// f(l, v) cos θ towards it). n, v, x, y: the surface frame (x, y tangents), alpha the lobe's rough GGX width.
vec3 scene_light_brdf(vec3 position, vec3 n, vec3 v, vec3 x, vec3 y, float alpha) {
    if (!scene_light_sized()) {
        vec3 l = normalize(LightPosition - position);
        float nl = dot(n, l);
        if (nl <= 0.0 || dot(n, v) <= 0.0) return vec3(0.0);
        return fx_environment_brdf(l, v, n, x, y) * nl;
    }
    if (dot(n, v) <= 0.0) return vec3(0.0);
    LightSampling s = light_sampling(position, n);
    alpha = clamp(alpha, 0.001, 1.0);
    // The lobe's directions count as `lobes` of them by how many of them meet the light, about
    // 64 min(1, Ω / 4πα²) (4πα² the lobe's solid angle): all from 16, none below 4 (the few that meet
    // a light much smaller than the lobe would only add lumps), linearly between. A light that fills much of the sky
    // (a panel just above the surface, or cutting through it) or lies close by adds cosine-distributed
    // directions, fully from 1.5 (area over the squared distance to its nearest point): the light's
    // own points, weighted by 1 / r², would stand out as dots there.
    float lights = float(s.count.x), hits = float(kFxLightLobeSamples) * min(1.0, s.solid / (4.0 * 3.14159265358979323846 * alpha * alpha));
    float lobes = float(kFxLightLobeSamples) * clamp((hits - 4.0) / 12.0, 0.0, 1.0);
    float cosines = float(kFxLightCosineSamples) * clamp(s.nearness - 0.5, 0.0, 1.0);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < s.count.x; ++j) {
        float pdf;
        vec3 l = light_sample(s, j, pdf);
        float nl = dot(n, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;  // as Lit draws such a BRDF black
        sum += f * (nl * s.radiance / (lights * pdf + lobes * light_lobe_pdf(n, v, l, alpha) + cosines * nl / 3.14159265358979323846));
    }
    vec3 lobe_sum = vec3(0.0);
    for (int i = 0; i < kFxLightLobeSamples && lobes > 0.0; ++i) {
        vec3 l = light_lobe_direction(n, v, x, y, i, alpha);
        float nl = dot(n, l), pdf = light_pdf_along(s, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;
        lobe_sum += f * (nl * s.radiance / (lights * pdf + lobes * light_lobe_pdf(n, v, l, alpha) + cosines * nl / 3.14159265358979323846));
    }
    vec3 cosine_sum = vec3(0.0);
    for (int i = 0; i < kFxLightCosineSamples && cosines > 0.0; ++i) {
        vec3 l = light_cosine_direction(n, x, y, i);
        float nl = dot(n, l), pdf = light_pdf_along(s, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;
        cosine_sum += f * (nl * s.radiance / (lights * pdf + lobes * light_lobe_pdf(n, v, l, alpha) + cosines * nl / 3.14159265358979323846));
    }
    return sum + lobe_sum * (lobes / float(kFxLightLobeSamples)) + cosine_sum * (cosines / float(kFxLightCosineSamples));
}
