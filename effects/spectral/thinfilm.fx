// Thin-film interference of seed 002 ch. 4.4 (Tables 5-8): the light spectrum times the film's
// reflectance per wavelength, integrated against the CIE colour matching functions (DOMAIN.md §3).
// The thesis' models are implemented as documented (PathDifference eq. 62, Fresnel = Code 15,
// FresnelAlternative eq. 65, Fabry-Pérot eq. 66 with its R); FresnelExact (Airy), Bubble (Sun) and
// MultiLayer (Hirayama, eq. 67) are exact. Every technique has a CPU reference
// (viewer/reference/thin_film_reference.cpp); the exact ones are checked against characteristic
// matrices, an independent method.
#include "standard.glsl"
#include "spectral.glsl"
#include "thin_film.glsl"
#include "environment_spectral_lobes.glsl"
#include "area_light.glsl"

uniform int LightSpectrum < string UIName = "Light spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                            string UIHelp = "The light's spectrum (spectra/library.txt; 5 = D65); a scene light spectrum (--light-spectrum, Scene tab) overrides it";
                            string SceneLight = "spectrum"; > = 5;
uniform float Brightness < string UIName = "Brightness"; float UIMin = 0; float UIMax = 8; float UIStep = 0.1; string UIGroup = "Lighting";
                           string UIHelp = "Scales the reflected light: 1 is physical (a perfect mirror under illuminant E gives Y = 1)"; > = 2.0;
uniform int Incidence < string UIName = "Angle of incidence from"; string UIWidget = "combo"; string UIItems = "view|light"; string UIGroup = "Lighting";
                        string UIHelp = "view: light arriving from the mirror direction of the eye (a uniform sky of the light spectrum; under --environment sky, the sky seen in that direction), and a sized scene light mirrored; light: the angle to the point light"; > = 0;

uniform float OuterIndex < string UIName = "Outer medium n0"; float UIMin = 1; float UIMax = 2.5; float UIStep = 0.01; string UIGroup = "Film"; int UIOrder = 1; > = 1.0;
uniform float FilmIndex < string UIName = "Film n1"; float UIMin = 1; float UIMax = 3; float UIStep = 0.01; string UIGroup = "Film"; int UIOrder = 2;
                          string UIHelp = "1.33: soap/water; 1.38: MgF2 coating; 2.0: a dense oxide"; > = 1.33;
uniform float SubstrateIndex < string UIName = "Substrate n2"; float UIMin = 1; float UIMax = 4; float UIStep = 0.01; string UIGroup = "Film"; int UIOrder = 3; > = 1.5;
uniform float SubstrateKappa < string UIName = "Substrate κ"; float UIMin = 0; float UIMax = 5; float UIStep = 0.01; string UIGroup = "Film"; int UIOrder = 4;
                               string UIHelp = "Extinction coefficient of the substrate, n2 + iκ (exact models only)"; > = 0.0;
uniform float Thickness < string UIName = "Thickness"; float UIMin = 0; float UIMax = 2000; float UIStep = 1; string UIUnits = "nm"; string UIGroup = "Film"; int UIOrder = 5;
                          string UIHelp = "Base thickness of the film (layer A in a stack)"; > = 100.0;
uniform float Variation < string UIName = "Variation"; float UIMin = 0; float UIMax = 2000; float UIStep = 1; string UIUnits = "nm"; string UIGroup = "Film"; int UIOrder = 6;
                          string UIHelp = "Height of the inverted paraboloid, in texture coordinates, added to the base thickness"; > = 300.0;

uniform float Roughness < string UIName = "Roughness"; float UIMin = 0; float UIMax = 0.75; float UIStep = 0.01; string UIGroup = "Film"; int UIOrder = 7;
                          string UIHelp = "A rough film (microfacet width α = Roughness²): it mirrors the environment and a sized light through a glossy lobe, split into four bands of viewing angle that each show the film at their own angle. 0: a smooth film; 0.75: the broadest lobe drawn. Only with Incidence = view (the light's incidence has no lobe). An approximation: under the sky about 0.1 CIEDE2000 from the exact integral on average at 0.2, 0.2 at 0.4, 0.35 at 0.7. Costs about 8x a smooth Fourier film at 0.4, 20x at 0.7"; > = 0.0;

uniform int Layers < string UIName = "Layers"; int UIMin = 1; int UIMax = 16; string UIGroup = "Stack"; int UIOrder = 1;
                     string UIHelp = "Films on the substrate, alternating A (n1, varying thickness) and B from the top"; > = 4;
uniform float SecondIndex < string UIName = "Layer B n"; float UIMin = 1; float UIMax = 3; float UIStep = 0.01; string UIGroup = "Stack"; int UIOrder = 2; > = 2.0;
uniform float FilmDispersion < string UIName = "Layer A dispersion B"; float UIMin = 0; float UIMax = 50000; float UIStep = 100; string UIUnits = "nm^2";
                               string UIGroup = "Stack"; int UIOrder = 4;
                               string UIHelp = "Cauchy: n(lambda) = n + B / lambda^2 (water ~3000, TiO2 ~40000); MultiLayer only"; > = 0.0;
uniform float SecondDispersion < string UIName = "Layer B dispersion B"; float UIMin = 0; float UIMax = 50000; float UIStep = 100; string UIUnits = "nm^2";
                                 string UIGroup = "Stack"; int UIOrder = 5; string UIHelp = "Cauchy B of layer B; MultiLayer only"; > = 0.0;
uniform float SecondThickness < string UIName = "Layer B thickness"; float UIMin = 0; float UIMax = 2000; float UIStep = 1; string UIUnits = "nm";
                                string UIGroup = "Stack"; int UIOrder = 3; > = 80.0;

#include "thinfilm_pixel.glsl"  // the film at a pixel, what it mirrors, a rough film's strata

// Eq. 62 / Code 13: the light angle refracted into the film, the eye's cosine squeezed to 0.9..1.
GLSLShader PathDifferenceFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            float cos_beta = refracted_cos(OuterIndex, FilmIndex, f.cos_light);
            float cos_eye = f.cos_view * 0.1 + 0.9;
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1))
                add_sample(xyz, ybar_sum, nm, fract(2.0 * f.thickness * FilmIndex * cos_beta * cos_eye / float(nm)));
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// The thesis' models assume light enters the film: past the film's critical angle (cos1 = 0, only
// when n1 < n0) their formulas divide 0 by 0, and the Fresnel-based ones return 1, total reflection
// (viewer/optics/thesis_models.hpp).

// Code 15 as printed: every angle and coefficient recomputed for each wavelength.
float durikovic(float cos0, float thickness, float nm) {
    float cos1 = refracted_cos(OuterIndex, FilmIndex, cos0);
    if (cos1 <= 0.0) return 1.0;  // past the film's critical angle: outside the model, total reflection
    float cos2 = refracted_cos(OuterIndex, SubstrateIndex, cos0);
    float gamma = kTwoPi / nm * (2.0 * FilmIndex * thickness * cos1);
    float cgamma = cos(gamma);
    vec2 r10 = fresnel_combined(cos1, cos0, FilmIndex, OuterIndex);
    vec2 r12 = fresnel_combined(cos1, cos2, FilmIndex, SubstrateIndex);
    vec2 result = (r10 + r12 * cgamma) / (1.0 + r12 * r10 * cgamma);
    return 0.5 * dot(result, result);
}

GLSLShader FresnelFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1))
                add_sample(xyz, ybar_sum, nm, durikovic(f.cos0, f.thickness, float(nm)));
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Code 15 with the wavelength-independent coefficients and products moved out of the loop.
GLSLShader FresnelFasterFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            float cos1 = refracted_cos(OuterIndex, FilmIndex, f.cos0);
            float cos2 = refracted_cos(OuterIndex, SubstrateIndex, f.cos0);
            vec2 r10 = fresnel_combined(cos1, f.cos0, FilmIndex, OuterIndex);
            vec2 r12 = fresnel_combined(cos1, cos2, FilmIndex, SubstrateIndex);
            vec2 r12r10 = r12 * r10;
            float path = kTwoPi * 2.0 * FilmIndex * f.thickness * cos1;
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
                float cgamma = cos(path / float(nm));
                vec2 result = (r10 + r12 * cgamma) / (1.0 + r12r10 * cgamma);
                add_sample(xyz, ybar_sum, nm, cos1 > 0.0 ? 0.5 * dot(result, result) : 1.0);
            }
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Eq. 64/65: phase from the path in the film minus the path outside, t = |1 - r|.
GLSLShader FresnelAlternativeFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            float cos1 = refracted_cos(OuterIndex, FilmIndex, f.cos0);
            float cos2 = refracted_cos(OuterIndex, SubstrateIndex, f.cos0);
            // Eq. 64's path in the film minus the path outside, 2dn1/cos1 - 2dn0 tan1 sin0, is by Snell
            // exactly 2dn1 cos1; written so, it does not lose the phase to cancellation near grazing
            // incidence in float (thick films, n1 = n0).
            float path = kTwoPi * 2.0 * f.thickness * FilmIndex * cos1;
            vec2 r01 = fresnel_combined(f.cos0, cos1, OuterIndex, FilmIndex);
            vec2 r10 = fresnel_combined(cos1, f.cos0, FilmIndex, OuterIndex);
            vec2 r12 = fresnel_combined(cos1, cos2, FilmIndex, SubstrateIndex);
            vec2 t01 = abs(1.0 - r01), t10 = abs(1.0 - r10);
            vec2 trt = t01 * r12 * t10, trrrt = t01 * r12 * r10 * r12 * t10;
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
                float delta = path / float(nm);
                vec2 sine = trt * sin(delta) + trrrt * sin(2.0 * delta);
                vec2 cosine = r01 * cos(delta) + trrrt * cos(2.0 * delta);
                // Clamped to 1: the truncated sum can exceed it (docs/thin-films.md).
                add_sample(xyz, ybar_sum, nm, cos1 > 0.0 ? min(0.5 * (dot(sine, sine) + dot(cosine, cosine)), 1.0) : 1.0);
            }
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Airy's sum for one film on a substrate n2 + iκ, per polarisation, in complex form (one step of
// eq. 67): exact, also past the critical angle and on metals.
vec4 fresnel_exact_colour(Film pixel) {
    vec3 xyz = vec3(0.0);
    float ybar_sum = 0.0;
    int stratum = 0;
    do {
        if (film_stratum_empty(stratum)) continue;
        Film f = film_stratum(pixel, stratum);
        ybar_sum = 0.0;
        vec2 n1 = vec2(FilmIndex, 0.0), n2 = vec2(SubstrateIndex, SubstrateKappa);
        vec2 cos1 = refracted_cos_c(OuterIndex, n1, f.cos0), cos2 = refracted_cos_c(OuterIndex, n2, f.cos0);
        Amplitude r01 = fresnel_c(vec2(OuterIndex, 0.0), vec2(f.cos0, 0.0), n1, cos1);
        Amplitude r12 = fresnel_c(n1, cos1, n2, cos2);
        vec2 path = kTwoPi * f.thickness * c_mul(n1, cos1);
        for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
            vec2 s = hirayama_step(r01.s, r12.s, path / float(nm));
            vec2 p = hirayama_step(r01.p, r12.p, path / float(nm));
            add_sample(xyz, ybar_sum, nm, 0.5 * (dot(s, s) + dot(p, p)));
        }
    } while (++stratum < film_strata_count);
    return film_colour(xyz, ybar_sum);
}

GLSLShader FresnelExactFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        color = fresnel_exact_colour(film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal))));
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Bump mapping (eq. 69, fig. 32/33): a procedural wave height h(u, v) = A sin(2πfu) sin(2πfv) tilts
// the normal in tangent space, n' = normalize(T (-dh/du) + B (-dh/dv) + N) with B = N x T, and
// thickens the film by WaveThickness · h; the film is then FresnelExact's.
uniform float WaveAmplitude < string UIName = "Wave amplitude"; float UIMin = 0; float UIMax = 0.1; float UIStep = 0.001; string UIGroup = "Bumps";
                              string UIHelp = "Height of the waves in texture units (BumpFresnelExact)"; > = 0.004;
uniform float WaveFrequency < string UIName = "Waves per texture unit"; float UIMin = 1; float UIMax = 64; string UIGroup = "Bumps"; > = 12.0;
uniform float WaveThickness < string UIName = "Thickness per height"; float UIMin = 0; float UIMax = 100000; string UIUnits = "nm";
                              string UIGroup = "Bumps"; string UIHelp = "Film thickness added per unit of wave height (crests are thicker)"; > = 10000.0;

GLSLShader BumpFresnelExactFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        vec3 n = normalize(fs_in.normal);
        vec3 t = normalize(fs_in.tangent - n * dot(n, fs_in.tangent));
        vec3 b = cross(n, t);
        float w = kTwoPi * WaveFrequency;
        // Reduced to one period before sin/cos: at 64 waves the argument reaches 400 rad, where float
        // sin/cos lose 1e-5 (as cd.fx found).
        vec2 phase = kTwoPi * fract(WaveFrequency * fs_in.uv);
        float height = WaveAmplitude * sin(phase.x) * sin(phase.y);
        vec2 slope = WaveAmplitude * w * vec2(cos(phase.x) * sin(phase.y), sin(phase.x) * cos(phase.y));
        vec3 tilted = -slope.x * t - slope.y * b + n;
        Film f = film_at(fs_in.world_position, tilted, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, tilted)));
        f.thickness = max(f.thickness + WaveThickness * height, 0.0);
        color = fresnel_exact_colour(f);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Eq. 48/49 (Sun): a free film in the outer medium, R = 2r²(1 - cos δ)/(1 + r⁴ - 2r² cos δ), evaluated
// as 4r² sin²(δ/2) / ((1 - r²)² + 4r² sin²(δ/2)): the same value without float cancellation near
// grazing incidence, where r² -> 1 and cos δ -> 1 (the printed form loses everything there).
// Past the critical angle of a film less dense than its surroundings the wave in the film decays
// (cos θ1 = iκ) and tunnels through a thin film: frustrated total reflection. Airy's sum with
// complex amplitudes then has |r| = 1, r² = exp(2iφ) and exp(2iδ) = e real, which gives
// R = (1 - e)² / ((1 - e)² + 4e sin²φ). Both cases are exact for the lossless free film.
GLSLShader BubbleFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            float ratio = OuterIndex / FilmIndex;
            // cos²θ1 without the cancellation of 1 - sin² near grazing incidence (see refracted_cos).
            float cos1_squared = (1.0 - ratio * ratio) + ratio * ratio * f.cos0 * f.cos0;
            if (cos1_squared >= 0.0) {
                float cos1 = sqrt(cos1_squared);
                vec2 r = fresnel_combined(f.cos0, cos1, OuterIndex, FilmIndex);
                vec2 r2 = r * r;
                vec2 one_minus_r2_squared = (1.0 - r2) * (1.0 - r2);
                float half_path = 0.5 * kTwoPi * 2.0 * FilmIndex * f.thickness * cos1;
                for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
                    float s = sin(half_path / float(nm));
                    vec2 numerator = 4.0 * r2 * s * s, denominator = one_minus_r2_squared + numerator;
                    // r² = 1 and sin = 0 together only at grazing incidence, where everything is reflected.
                    vec2 reflectance = mix(vec2(1.0), numerator / denominator, greaterThan(denominator, vec2(0.0)));
                    add_sample(xyz, ybar_sum, nm, 0.5 * (reflectance.x + reflectance.y));
                }
            } else {
                float kappa = sqrt(-cos1_squared);
                Amplitude r = fresnel_c(vec2(OuterIndex, 0.0), vec2(f.cos0, 0.0), vec2(FilmIndex, 0.0), vec2(0.0, kappa));
                // sin²φ = (1 - Re r²) / 2 for |r| = 1, per polarisation.
                vec2 sin2_phi = 0.5 * (1.0 - vec2(c_mul(r.s, r.s).x, c_mul(r.p, r.p).x));
                float decay = 2.0 * kTwoPi * FilmIndex * f.thickness * kappa;  // -ln e times the wavelength
                for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
                    float e = exp(-decay / float(nm));
                    vec2 numerator = vec2((1.0 - e) * (1.0 - e)), denominator = numerator + 4.0 * e * sin2_phi;
                    vec2 reflectance = mix(vec2(1.0), numerator / denominator, greaterThan(denominator, vec2(0.0)));
                    add_sample(xyz, ybar_sum, nm, 0.5 * (reflectance.x + reflectance.y));
                }
            }
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Eq. 66 with the thesis' R = ½(|r∥| + |r⊥|): reflected = 1 - T of an etalon of the film.
GLSLShader FabryPerotFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            float cos1 = refracted_cos(OuterIndex, FilmIndex, f.cos0);
            vec2 r = abs(fresnel_combined(f.cos0, cos1, OuterIndex, FilmIndex));
            float mirror = 0.5 * (r.x + r.y);
            float half_path = 0.5 * kTwoPi * 2.0 * FilmIndex * f.thickness * cos1;
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
                float s = sin(half_path / float(nm));
                // 1 - 1/(1 + F s²) with F = 4R/(1 - R)², as 4R s² / ((1 - R)² + 4R s²): no infinite finesse
                // at grazing incidence (R = 1); a film of no thickness (s = 0) there reflects nothing.
                float numerator = 4.0 * mirror * s * s, denominator = (1.0 - mirror) * (1.0 - mirror) + numerator;
                add_sample(xyz, ybar_sum, nm, cos1 > 0.0 ? (denominator > 0.0 ? numerator / denominator : 0.0) : 1.0);
            }
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// The stack: layer j (1 = top) is A (FilmIndex, the fragment's thickness) for odd j, else B.
vec2 layer_index(int j) { return vec2(j % 2 == 1 ? FilmIndex : SecondIndex, 0.0); }
// With Cauchy dispersion (ch. 5.1: indices that vary with the wavelength), for MultiLayer.
vec2 layer_index_at(int j, float nm) { return layer_index(j) + vec2((j % 2 == 1 ? FilmDispersion : SecondDispersion) / (nm * nm), 0.0); }
float layer_thickness(int j, float thickness_a) { return j % 2 == 1 ? thickness_a : SecondThickness; }

// Grazing incidence (cos θ0 = 0, silhouettes): a stack with any interface reflects everything (the
// limit of Airy's and Hirayama's sums, which evaluate 0/0 there when a layer matches the outer
// medium); a stack matched to the outer medium throughout has no interface and reflects nothing.
float grazing_reflectance(vec2 na, vec2 nb, vec2 substrate, int count) {
    vec2 n0 = vec2(OuterIndex, 0.0);
    return na == n0 && (count == 1 || nb == n0) && substrate == n0 ? 0.0 : 1.0;
}

// Eq. 67 as the thesis ran it: every layer's angle and coefficients recomputed for each wavelength,
// which also lets the indices follow the wavelength (Cauchy dispersion).
float multilayer(float cos0, float thickness_a, float nm) {
    int count = clamp(Layers, 1, 16);
    vec2 substrate = vec2(SubstrateIndex, SubstrateKappa);
    if (cos0 <= 0.0) return grazing_reflectance(layer_index_at(1, nm), layer_index_at(2, nm), substrate, count);
    vec2 n_last = layer_index_at(count, nm), cos_last = refracted_cos_c(OuterIndex, n_last, cos0);
    Amplitude gamma = fresnel_c(n_last, cos_last, substrate, refracted_cos_c(OuterIndex, substrate, cos0));
    for (int j = count; j >= 1; --j) {
        vec2 n = layer_index_at(j, nm), cos_j = refracted_cos_c(OuterIndex, n, cos0);
        vec2 n_above = j == 1 ? vec2(OuterIndex, 0.0) : layer_index_at(j - 1, nm);
        vec2 cos_above = j == 1 ? vec2(cos0, 0.0) : refracted_cos_c(OuterIndex, n_above, cos0);
        Amplitude r = fresnel_c(n_above, cos_above, n, cos_j);
        vec2 phase = kTwoPi / nm * layer_thickness(j, thickness_a) * c_mul(n, cos_j);
        gamma.s = hirayama_step(r.s, gamma.s, phase);
        gamma.p = hirayama_step(r.p, gamma.p, phase);
    }
    return 0.5 * (dot(gamma.s, gamma.s) + dot(gamma.p, gamma.p));
}

GLSLShader MultiLayerFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1))
                add_sample(xyz, ybar_sum, nm, multilayer(f.cos0, f.thickness, float(nm)));
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// The same stack with every coefficient precomputed: only A and B alternate, so four interfaces
// (top, A->B, B->A, bottom) and two phase paths serve all wavelengths.
GLSLShader MultiLayerFasterFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Film pixel = film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal)));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        int stratum = 0;
        do {
            if (film_stratum_empty(stratum)) continue;
            Film f = film_stratum(pixel, stratum);
            ybar_sum = 0.0;
            int count = clamp(Layers, 1, 16);
            vec2 n0 = vec2(OuterIndex, 0.0), na = layer_index(1), nb = layer_index(2), ns = vec2(SubstrateIndex, SubstrateKappa);
            vec2 cos0 = vec2(f.cos0, 0.0), cos_a = refracted_cos_c(OuterIndex, na, f.cos0), cos_b = refracted_cos_c(OuterIndex, nb, f.cos0);
            vec2 cos_s = refracted_cos_c(OuterIndex, ns, f.cos0);
            Amplitude top = fresnel_c(n0, cos0, na, cos_a), a_to_b = fresnel_c(na, cos_a, nb, cos_b), b_to_a = fresnel_c(nb, cos_b, na, cos_a);
            Amplitude bottom = count % 2 == 1 ? fresnel_c(na, cos_a, ns, cos_s) : fresnel_c(nb, cos_b, ns, cos_s);
            vec2 path_a = kTwoPi * f.thickness * c_mul(na, cos_a), path_b = kTwoPi * SecondThickness * c_mul(nb, cos_b);
            for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
                float inverse_nm = 1.0 / float(nm);
                Amplitude gamma = bottom;
                if (f.cos0 <= 0.0) {
                    add_sample(xyz, ybar_sum, nm, grazing_reflectance(na, nb, ns, count));
                    continue;
                }
                for (int j = count; j >= 1; --j) {
                    Amplitude r = j == 1 ? top : (j % 2 == 1 ? b_to_a : a_to_b);
                    vec2 phase = (j % 2 == 1 ? path_a : path_b) * inverse_nm;
                    gamma.s = hirayama_step(r.s, gamma.s, phase);
                    gamma.p = hirayama_step(r.p, gamma.p, phase);
                }
                add_sample(xyz, ybar_sum, nm, 0.5 * (dot(gamma.s, gamma.s) + dot(gamma.p, gamma.p)));
            }
        } while (++stratum < film_strata_count);
        color = film_colour(xyz, ybar_sum);
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

#include "thin_film_fourier.glsl"  // the Fourier-domain films (Belcour & Barla 2017)

GLSLShader FresnelFourierFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        color = fourier_film_colour(film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal))), vec2(SubstrateIndex, SubstrateKappa));
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

GLSLShader BubbleFourierFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        color = fourier_film_colour(film_at(fs_in.world_position, fs_in.normal, fs_in.uv, fx_pixel_turn(mirror_of_eye(fs_in.world_position, fs_in.normal))), vec2(OuterIndex, 0.0));
        fx_capture();
        fx_capture_footprint = film_footprint;
    }
}

// Thickness from a colour (docs/plugins.md): the Plugins tab or `fxview plugin run
// effects/spectral/thinfilm.fx ThicknessFromColour --set TargetColour=R,G,B` finds the thickness whose
// interference colour at normal incidence has the target's chromaticity (Airy's exact reflectance),
// and lists the other interference orders that match as well.
uniform vec3 TargetColour < string UIName = "Target colour"; string UIWidget = "color"; string UIGroup = "Thickness from colour";
                            string UIHelp = "Linear RGB of an observed film colour (e.g. a picked pixel); its chromaticity is matched, not its brightness"; > = {0.10, 0.22, 0.35};
plugin ThicknessFromColour < string Type = "film-fit"; string UIName = "Thickness from a colour";
                             string Target = "TargetColour"; string Vary = "Thickness";
                             string OuterIndex = "OuterIndex"; string FilmIndex = "FilmIndex"; string SubstrateIndex = "SubstrateIndex";
                             string SubstrateKappa = "SubstrateKappa"; string Light = "LightSpectrum"; string Observer = "Observer";
                             string Lower = "Lower"; string Upper = "Upper"; string Technique = "FresnelExact"; float Angle = 0; >;

technique PathDifference { pass p0 { VertexShader = StandardVS; FragmentShader = PathDifferenceFS; } }
technique Fresnel { pass p0 { VertexShader = StandardVS; FragmentShader = FresnelFS; } }
technique FresnelFaster { pass p0 { VertexShader = StandardVS; FragmentShader = FresnelFasterFS; } }
technique FresnelAlternative { pass p0 { VertexShader = StandardVS; FragmentShader = FresnelAlternativeFS; } }
technique FresnelExact < bool Default = true; > { pass p0 { VertexShader = StandardVS; FragmentShader = FresnelExactFS; } }
technique BumpFresnelExact { pass p0 { VertexShader = StandardVS; FragmentShader = BumpFresnelExactFS; } }
technique Bubble { pass p0 { VertexShader = StandardVS; FragmentShader = BubbleFS; } }
technique FabryPerot { pass p0 { VertexShader = StandardVS; FragmentShader = FabryPerotFS; } }
technique MultiLayer { pass p0 { VertexShader = StandardVS; FragmentShader = MultiLayerFS; } }
technique MultiLayerFaster { pass p0 { VertexShader = StandardVS; FragmentShader = MultiLayerFasterFS; } }
technique FresnelFourier < string UIName = "Fresnel, Fourier series (fast)";
                           string UIHelp = "FresnelExact's film as a short interference series with precomputed light x CMF transforms; indices independent of wavelength"; >
    { pass p0 { VertexShader = StandardVS; FragmentShader = FresnelFourierFS; } }
technique BubbleFourier < string UIName = "Bubble, Fourier series (fast)";
                          string UIHelp = "Bubble's free film as a short interference series with precomputed light x CMF transforms"; >
    { pass p0 { VertexShader = StandardVS; FragmentShader = BubbleFourierFS; } }
