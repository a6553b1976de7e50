// Diffraction at the tracks of a CD or DVD (seed 002 ch. 4.5, DOMAIN.md §4) on the `disc` mesh: the
// tracks are circles around the texture centre (0.5, 0.5), so the grating vector g (across the
// tracks) is the radial direction in texture space mapped to the surface through its tangent frame.
// Each wavelength's diffracted intensity is weighted by the light spectrum and integrated against
// the CMFs; a substrate spectrum adds the disc's own diffuse colour and a cube map its mirrored
// surroundings (fig. 34, 36).
// Thesis: eq. 70-72 as documented. Grating: Fraunhofer diffraction of a square patch of N tracks
// (N tracks across, N·d along them), the phase across the tracks (orders where d (l + v)·g = mλ) and
// along them (all orders lie where (l + v)·t = 0; the zero order is the mirror highlight), averaged
// over each pixel's footprint. docs/diffraction.md.
// Orders (the default): an energy-true grating lit by the scene's light as what it is, a point, a
// sphere (a lamp) or a flat disc or rectangle (a ceiling panel, a window; area_light.glsl): each
// order m reflects the light like a mirror with its own efficiency, turned by the grating equation
// (viewer/optics/grating_orders.hpp), so a sized light shows a rainbow sector and the mirror order
// the light's own colour; the number of coherently lit tracks sets each order's width, not its energy.
// CPU references: viewer/reference/cd_reference.cpp.
#include "standard.glsl"
#include "spectral.glsl"
#include "environment_spectral.glsl"
#include "area_light.glsl"
#include "fullscreen.glsl"

uniform int LightSpectrum < string UIName = "Light spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                            string UIHelp = "The light's spectrum (spectra/library.txt; 5 = D65); a scene light spectrum (--light-spectrum, Scene tab) overrides it";
                            string SceneLight = "spectrum"; > = 5;
uniform int SubstrateSpectrum < string UIName = "Substrate spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                                string UIHelp = "Reflectance of the disc's metal coating"; > = 0;
uniform float SubstrateWeight < string UIName = "Substrate kd"; float UIMin = 0; float UIMax = 1; string UIGroup = "Spectra"; > = 0.15;
uniform float Brightness < string UIName = "Brightness"; float UIMin = 0; float UIMax = 8; float UIStep = 0.1; string UIGroup = "Lighting"; > = 1.0;

uniform float TrackSpacing < string UIName = "Track spacing d"; float UIMin = 300; float UIMax = 5000; string UIUnits = "nm"; string UIGroup = "Disc";
                             string UIHelp = "1600 nm: CD; 740 nm: DVD"; > = 1600.0;
uniform float Threshold < string UIName = "Threshold"; float UIMin = 0; float UIMax = 1; string UIGroup = "Simple model (hard cut)";
                          string UIHelp = "Intensities below it are cut to 0"; > = 0.5;
uniform int Tracks < string UIName = "Illuminated tracks N"; int UIMin = 1; int UIMax = 200; string UIGroup = "Grating";
                     string UIHelp = "Tracks lit coherently (a square patch N tracks wide and as long): more tracks give narrower orders and a smaller mirror highlight. Orders narrower than a pixel are averaged over it, so they stay smooth but dim; raise Brightness to see them"; > = 60;

uniform float Reflectance < string UIName = "Coating reflectance"; float UIMin = 0; float UIMax = 1; string UIGroup = "Diffraction orders";
                            string UIHelp = "Of the disc's metal coating: the light all orders together reflect"; > = 0.9;
uniform float ZeroOrder < string UIName = "Mirror share"; float UIMin = 0; float UIMax = 1; string UIGroup = "Diffraction orders";
                          string UIHelp = "Part of the reflected light in the plain mirror image of the lamp; the rest goes into the rainbow orders"; > = 0.35;
uniform float PitFraction < string UIName = "Pit width"; float UIMin = 0.05; float UIMax = 0.95; string UIGroup = "Diffraction orders";
                            string UIHelp = "Part of each track period the pits fill: how the rainbow light is shared between the first, second, third ... orders"; > = 0.35;
uniform int EnvironmentBand < string UIName = "Environment band"; int UIMin = 1; int UIMax = 50; string UIUnits = "nm"; string UIGroup = "Diffraction orders";
                               string UIHelp = "Under --environment sky or studio: each order looks up the surroundings once per band of this many nm (1: at every sample; 10: the sun's rainbow image moves 0.4 degrees per band in the first order)"; > = 10;
uniform int LampBand < string UIName = "Lamp band"; int UIMin = 1; int UIMax = 32; string UIUnits = "nm"; string UIGroup = "Diffraction orders";
                        string UIHelp = "Under a large light (a ceiling panel, a window) each order finds the light's edge at both ends of a band of this many nm and follows it linearly between: large lights cost about what small ones do (1: at every sample; small lights always are)"; > = 16;
uniform float Lamp < string UIName = "Lamp"; float UIMin = 0; float UIMax = 4; float UIStep = 0.05; string UIGroup = "Diffraction orders";
                     string UIHelp = "Scales the scene's light (0: the disc is lit by the environment alone, --environment sky or studio). A scene light intensity (--light-intensity, Scene tab) sets it: E / (π Y) for the light spectrum's luminance Y";
                     string SceneLight = "spectral-brightness"; > = 1.0;

// The surroundings mirrored in the disc (fig. 34, 36): a cube map added in RGB after the spectral part.
texture EnvironmentTexture < string ResourceName = "sky_cross.png"; string ResourceType = "CUBE"; string ColorSpace = "sRGB"; >;
uniform samplerCube Environment = sampler_state { Texture = <EnvironmentTexture>; MinFilter = Linear; MagFilter = Linear; };
uniform float EnvironmentWeight < string UIName = "Environment"; float UIMin = 0; float UIMax = 1; string UIGroup = "Disc";
                                  string UIHelp = "Weight of the mirrored cube map (0: off)"; > = 0.25;

struct Disc { vec3 n, l, v, across, along; };

// Under a spectral scene environment (--environment sky or studio) the Orders technique diffracts the
// surroundings themselves, so this stand-in is off there.
bool orders_see_environment() { return spectral_environment(); }
vec3 environment(Disc d) { return EnvironmentWeight * texture(Environment, reflect(-d.v, d.n)).rgb; }

Disc disc_at(vec3 position, vec3 normal, vec3 tangent, vec2 uv) {
    Disc d;
    d.n = normalize(normal);
    d.l = normalize(LightPosition - position);
    d.v = normalize(CameraPosition - position);
    vec3 t = normalize(tangent - d.n * dot(d.n, tangent));
    vec3 b = cross(d.n, t);
    vec2 radial = uv - 0.5;
    // At the centre the direction is undefined; any will do there.
    d.across = dot(radial, radial) > 0.0 ? normalize(radial.x * t + radial.y * b) : t;
    d.along = cross(d.n, d.across);
    return d;
}

void add_sample(inout vec3 xyz, inout float ybar_sum, int nm, float diffraction, float diffuse) {
    vec3 cmf = cmf_at(nm);
    xyz += spectrum_at(LightSpectrum, nm) * (diffraction + SubstrateWeight * spectrum_at(SubstrateSpectrum, nm) * diffuse) * cmf;
    ybar_sum += cmf.y;
}

GLSLShader ThesisFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Disc d = disc_at(fs_in.world_position, fs_in.normal, fs_in.tangent, fs_in.uv);
        float influence = abs(dot(d.along, d.l));
        float spacing = TrackSpacing * (1.0 + 2.0 * influence);  // d across the tracks, 3d along them
        float path = spacing * abs(dot(d.n, d.v) - dot(d.n, d.l));
        float diffuse = max(dot(d.n, d.l), 0.0);
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
            float intensity = fract(path / float(nm));
            add_sample(xyz, ybar_sum, nm, intensity > Threshold ? intensity : 0.0, diffuse);
        }
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness) + environment(d), 1.0);
        fx_capture();
    }
}

const float PI = 3.14159265359;

// sinc(a / π) = sin(a) / a for |a| < 1 from its series (the quotient of a rounded sine by a small a
// would lose digits); the error of the omitted term is a^10 / 4e7 < 3e-8.
float sinc_series(float a) {
    float a2 = a * a;
    return 1.0 - a2 / 6.0 * (1.0 - a2 / 20.0 * (1.0 - a2 / 42.0 * (1.0 - a2 / 72.0)));
}

vec2 turned(vec2 phasor, vec2 turn) { return vec2(phasor.x * turn.x - phasor.y * turn.y, phasor.x * turn.y + phasor.y * turn.x); }

// The N-track term (sin Nπx / (N sin πx))² averaged over [x ± w/2]: its Fourier series (the Fejér
// kernel) times the box's transform, (1/N²)[N + 2 Σ_{k<N} (N−k) cos(2πkx) sinc(kw)]. cos(2πkx) and
// sin(πkw) come from turning phasors, so no sine sees a large argument.
float tracks_average(float x, float w, int n) {
    if (n <= 1) return 1.0;
    x -= floor(x + 0.5);
    float h = w - 2.0 * floor(0.5 * w);  // sin(πkw) = sin(πkh) for integer k
    vec2 turn_x = vec2(cos(2.0 * PI * x), sin(2.0 * PI * x)), phase_x = turn_x;
    vec2 turn_w = vec2(cos(PI * h), sin(PI * h)), phase_w = turn_w;
    float sum = 0.0;
    for (int k = 1; k < n; ++k) {
        float a = PI * float(k) * w;
        sum += float(n - k) * phase_x.x * (a < 1.0 ? sinc_series(a) : phase_w.y / a);
        phase_x = turned(phase_x, turn_x);
        phase_w = turned(phase_w, turn_w);
    }
    return (float(n) + 2.0 * sum) / float(n * n);
}

// Si(2πz) − sin²(πz)/(πz) = π ∫₀ᶻ sinc²: the sine integral from its series up to 2π|z| = 4 and from
// E₁'s continued fraction beyond (12 terms: 6e-9 at 4); trigonometric functions see z's fraction only.
vec2 complex_divide(vec2 a, vec2 b) { return vec2(a.x * b.x + a.y * b.y, a.y * b.x - a.x * b.y) / dot(b, b); }

float sinc_squared_integral(float z) {
    float t = 2.0 * PI * abs(z), r = abs(z) - floor(abs(z) + 0.5), si;
    if (t <= 4.0) {
        float term = t, t2 = t * t;
        si = t;
        for (int k = 1; k < 12; ++k) {
            term *= -t2 / (float(2 * k) * float(2 * k + 1));
            si += term / float(2 * k + 1);
        }
    } else {
        vec2 f = vec2(25.0, t);
        for (int i = 12; i >= 1; --i) f = vec2(float(2 * i - 1), t) - float(i * i) * complex_divide(vec2(1.0, 0.0), f);
        si = 0.5 * PI + complex_divide(vec2(cos(2.0 * PI * r), -sin(2.0 * PI * r)), f).y;
    }
    float s = sin(PI * r);
    float value = abs(z) > 0.0 ? (si - s * s / (PI * abs(z))) / PI : 0.0;
    return sign(z) * value;
}

float sinc_squared(float z) {
    float r = z - 2.0 * floor(0.5 * z + 0.5);  // sin(πz) = sin(πr)
    float a = PI * z, s = abs(a) < 1.0 ? sinc_series(a) : sin(PI * r) / a;
    return s * s;
}

// The along-track term sinc²(Ny) of the patch averaged over [y ± w/2]. Below 1/20 of a fringe the
// difference of the integrals would cancel in float: Simpson's rule, exact there to 3e-7.
float patch_average(float y, float w, int n) {
    float z = float(n) * y, width = float(n) * w;
    if (width < 0.05) return (sinc_squared(z - 0.5 * width) + 4.0 * sinc_squared(z) + sinc_squared(z + 0.5 * width)) / 6.0;
    return (sinc_squared_integral(z + 0.5 * width) - sinc_squared_integral(z - 0.5 * width)) / width;
}

GLSLShader GratingFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Disc d = disc_at(fs_in.world_position, fs_in.normal, fs_in.tangent, fs_in.uv);
        // Path differences in nm: between neighbouring tracks, and along a track per track spacing.
        float across = TrackSpacing * dot(d.l + d.v, d.across), along = TrackSpacing * dot(d.l + d.v, d.along);
        // The pixel's extent in both: the box the orders are averaged over.
        vec2 footprint = vec2(abs(dFdxFine(across)) + abs(dFdyFine(across)), abs(dFdxFine(along)) + abs(dFdyFine(along)));
        float diffuse = max(dot(d.n, d.l), 0.0);
        bool lit = dot(d.n, d.l) > 0.0 && dot(d.n, d.v) > 0.0;
        int tracks = max(Tracks, 1);
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
            float wavelength = float(nm);
            float intensity = lit ? patch_average(along / wavelength, footprint.y / wavelength, tracks) : 0.0;
            // Past the patch's fringes the product is below anything the colour shows.
            if (intensity > 1e-9) intensity *= tracks_average(across / wavelength, footprint.x / wavelength, tracks);
            add_sample(xyz, ybar_sum, nm, intensity, diffuse);
        }
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness) + environment(d), 1.0);
        fx_capture();
        fx_capture_footprint = vec4(footprint, 0.0, 0.0);
    }
}

#include "cd_orders.glsl"  // the orders under the scene's light, and the table they read

GLSLShader OrdersFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Disc d = disc_at(fs_in.world_position, fs_in.normal, fs_in.tangent, fs_in.uv);
        // A flat light (area_light.glsl) is looked up by the ray of each order; `edge` then bounds the
        // chord from its centre to any of its points: those within its half diagonal ρ of the centre
        // lie within asin(ρ / distance) of it, as a sphere of radius ρ.
        bool flat_lamp = flat_light();
        float reach_of_light = flat_lamp ? (flat_light_is_disc() ? LightHalfSize.x : length(LightHalfSize)) : max(LightRadius, 0.0);
        float light_distance = length(LightPosition - fs_in.world_position);
        float edge = flat_lamp && reach_of_light >= light_distance ? 2.0 : light_edge_chord(reach_of_light / light_distance);
        vec3 view = vec3(dot(d.v, d.across), dot(d.v, d.along), dot(d.v, d.n));
        vec3 light = vec3(dot(d.l, d.across), dot(d.l, d.along), dot(d.l, d.n));
        // How far the view and the track direction turn across the pixel: each order's image is
        // spread over that besides its coherence width.
        float view_spread = length(dFdxFine(d.v)) + length(dFdyFine(d.v));
        float turn_spread = length(dFdxFine(d.across)) + length(dFdyFine(d.across));
        float diffuse = max(dot(d.n, d.l), 0.0) * Lamp;
        if (flat_lamp) diffuse = flat_light_factors(fs_in.world_position, d.n, d.v, 1.0, false).x * Lamp;
        bool surroundings = orders_see_environment();
        vec3 lamp = vec3(0.0);
        FlatLightView flat_view = flat_light_view(fs_in.world_position);
        if (flat_lamp && flat_light_is_disc()) lamp_orders(true, true, d, flat_view, view, light, edge, view_spread, turn_spread, lamp);
        else if (flat_lamp) lamp_orders(true, false, d, flat_view, view, light, edge, view_spread, turn_spread, lamp);
        else lamp_orders(false, false, d, flat_view, view, light, edge, view_spread, turn_spread, lamp);
        vec4 coating = coating_sums();  // Σ S R x̄ȳz̄, Σ ȳ
        vec3 xyz = SubstrateWeight * diffuse * coating.xyz + Reflectance * Lamp * lamp;
        if (surroundings && view.z > 0.0) xyz += Reflectance * environment_orders(d, view);
        float ybar_sum = coating.w;
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness) + (surroundings ? vec3(0.0) : environment(d)), 1.0);
        fx_capture();
        fx_capture_footprint = vec4(view_spread, turn_spread, 0.0, 0.0);
    }
}

technique Orders < bool Default = true; string UIName = "Diffraction orders (lamps, energy-true)"; > {
    pass table { VertexShader = FullscreenVS; FragmentShader = OrdersTableFS; Draw = Buffer; DepthTestEnable = false; RenderColorTarget0 = OrdersTableTarget; }
    pass p0 { VertexShader = StandardVS; FragmentShader = OrdersFS; }
}
technique Thesis < string UIName = "Simple model (hard cut)"; > { pass p0 { VertexShader = StandardVS; FragmentShader = ThesisFS; } }
technique Grating < string UIName = "Grating (point light, peak 1)"; > { pass p0 { VertexShader = StandardVS; FragmentShader = GratingFS; } }
