// Diffraction at the tracks of a CD or DVD (seed 002 ch. 4.5, DOMAIN.md §4) on the `disc` mesh: the
// tracks are circles around the texture centre (0.5, 0.5), so the grating vector g (across the
// tracks) is the radial direction in texture space mapped to the surface through its tangent frame.
// Each wavelength's diffracted intensity is weighted by the light spectrum and integrated against
// the CMFs; a substrate spectrum adds the disc's own diffuse colour and a cube map its mirrored
// surroundings (fig. 34, 36).
// Thesis: eq. 70-72 as documented. Grating: the Fraunhofer interference of N tracks, exact for a
// reflection grating of N illuminated tracks (orders where d (l + v)·g = mλ).
// CPU references: viewer/reference/cd_reference.cpp.
#include "standard.glsl"
#include "spectral.glsl"

uniform int LightSpectrum < string UIName = "Light spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                            string UIHelp = "Index in spectra/library.txt (5 = D65)"; > = 5;
uniform int SubstrateSpectrum < string UIName = "Substrate spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                                string UIHelp = "Reflectance of the disc's coating (the thesis used gold, fig. 36b)"; > = 0;
uniform float SubstrateWeight < string UIName = "Substrate kd"; float UIMin = 0; float UIMax = 1; string UIGroup = "Spectra"; > = 0.15;
uniform float Brightness < string UIName = "Brightness"; float UIMin = 0; float UIMax = 8; float UIStep = 0.1; string UIGroup = "Lighting"; > = 1.0;

uniform float TrackSpacing < string UIName = "Track spacing d"; float UIMin = 300; float UIMax = 5000; string UIUnits = "nm"; string UIGroup = "Disc";
                             string UIHelp = "1600 nm: CD; 740 nm: DVD"; > = 1600.0;
uniform float Threshold < string UIName = "Threshold"; float UIMin = 0; float UIMax = 1; string UIGroup = "Thesis (eq. 72)";
                          string UIHelp = "Intensities below it are cut to 0 (the thesis' hard cut)"; > = 0.5;
uniform int Tracks < string UIName = "Illuminated tracks N"; int UIMin = 1; int UIMax = 200; string UIGroup = "Grating";
                     string UIHelp = "More tracks: sharper orders (width about 1/N); beyond ~100 they get narrower than the 1 nm sampling"; > = 60;

// The surroundings mirrored in the disc (fig. 34, 36): a cube map added in RGB after the spectral part.
texture EnvironmentTexture < string ResourceName = "sky_cross.png"; string ResourceType = "CUBE"; string ColorSpace = "sRGB"; >;
uniform samplerCube Environment = sampler_state { Texture = <EnvironmentTexture>; MinFilter = Linear; MagFilter = Linear; };
uniform float EnvironmentWeight < string UIName = "Environment"; float UIMin = 0; float UIMax = 1; string UIGroup = "Disc";
                                  string UIHelp = "Weight of the mirrored cube map (0: off)"; > = 0.25;

struct Disc { vec3 n, l, v, across, along; };

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

GLSLShader GratingFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Disc d = disc_at(fs_in.world_position, fs_in.normal, fs_in.tangent, fs_in.uv);
        float path = TrackSpacing * dot(d.l + d.v, d.across);  // nm between neighbouring tracks
        float diffuse = max(dot(d.n, d.l), 0.0);
        bool lit = dot(d.n, d.l) > 0.0 && dot(d.n, d.v) > 0.0;
        int tracks = max(Tracks, 1);
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
            // The intensity has period 1 in x = path / nm: reduce x to [-0.5, 0.5) first, so that sin()
            // sees small arguments and the quotient stays accurate next to an order (x near 0).
            float x = path / float(nm);
            float a = 3.14159265359 * (x - floor(x + 0.5));
            float s = float(tracks) * sin(a);
            float ratio = abs(s) > 1e-6 ? sin(float(tracks) * a) / s : 1.0;
            add_sample(xyz, ybar_sum, nm, lit ? ratio * ratio : 0.0, diffuse);
        }
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness) + environment(d), 1.0);
        fx_capture();
    }
}

technique Thesis { pass p0 { VertexShader = StandardVS; FragmentShader = ThesisFS; } }
technique Grating { pass p0 { VertexShader = StandardVS; FragmentShader = GratingFS; } }
