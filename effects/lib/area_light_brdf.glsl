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
    // 89 points (34 left 1-1.5 % errors on a Lambertian surface), 144 where the horizon crosses the light.
    float cos_theta = dot(n, s.centre);
    s.count = flat_light_count(cos_theta * cos_theta < solid / 3.14159265 ? 144.0 : 89.0);
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
    // The lobe's directions count as `lobes` of them: all where the light's solid angle exceeds the
    // lobe's (about 4π α²) by half, none where the lobe is twice the light's (there they would only
    // add lumps: few of them meet the light), linearly between.
    float lights = float(s.count.x), lobes = float(kFxLightLobeSamples) * clamp(s.solid / (4.0 * 3.14159265358979323846 * alpha * alpha) - 0.5, 0.0, 1.0);
    vec3 sum = vec3(0.0);
    for (int j = 0; j < s.count.x; ++j) {
        float pdf;
        vec3 l = light_sample(s, j, pdf);
        float nl = dot(n, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;  // as Lit draws such a BRDF black
        sum += f * (nl * s.radiance / (lights * pdf + lobes * light_lobe_pdf(n, v, l, alpha)));
    }
    vec3 lobe_sum = vec3(0.0);
    for (int i = 0; i < kFxLightLobeSamples && lobes > 0.0; ++i) {
        vec3 l = light_lobe_direction(n, v, x, y, i, alpha);
        float nl = dot(n, l), pdf = light_pdf_along(s, l);
        if (nl <= 0.0 || !(pdf > 0.0)) continue;
        vec3 f = fx_environment_brdf(l, v, n, x, y);
        if (any(isnan(f)) || any(isinf(f))) continue;
        lobe_sum += f * (nl * s.radiance / (lights * pdf + lobes * light_lobe_pdf(n, v, l, alpha)));
    }
    return sum + lobe_sum * (lobes / float(kFxLightLobeSamples));
}
