// Wavelength-based lighting of seed 002 (ch. 4.2-4.3, Tables 3 and 4): light and object spectra
// multiplied per wavelength (eq. 56), shaded, and integrated against the CIE colour matching
// functions in the fragment shader; XYZ -> linear sRGB by eq. 9. Every technique has a CPU
// reference (viewer/reference/spectral_reference.cpp) that `fxview compare` checks it against.
// Under a scene environment with a spectral form (`--environment sky`, `studio`, `furnace`) every
// technique but the two Constant ones is lit by it too: its spectral radiance, gathered by the
// diffuse and highlight lobes (environment_spectral_lobes.glsl), added to the lamp's light.
#include "standard.glsl"
#include "spectral.glsl"
#include "environment_spectral_lobes.glsl"
#include "sphere_lamp.glsl"
#include "area_light.glsl"

// Indices into spectra/library.txt (`fxview spectra list`).
uniform int LightSpectrum < string UIName = "Light spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                            string UIHelp = "The light's spectrum (spectra/library.txt; 5 = D65); a scene light spectrum (--light-spectrum, Scene tab) overrides it";
                            string SceneLight = "spectrum"; > = 5;
uniform int ObjectSpectrum < string UIName = "Object spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                             string UIHelp = "Index in spectra/library.txt (10-23 = CIE test colour samples)"; > = 14;
uniform float Brightness < string UIName = "Brightness"; float UIMin = 0; float UIMax = 8; float UIStep = 0.1; string UIGroup = "Lighting";
                           string UIHelp = "Intensity of the lamp (the scene's light); an environment lights the object at its own intensity. A scene light intensity (--light-intensity, Scene tab) sets it: E / (π Y) for the light spectrum's luminance Y";
                           string SceneLight = "spectral-brightness"; > = 2.0;
uniform float Kd < string UIName = "Diffuse kd"; float UIMin = 0; float UIMax = 1; string UIGroup = "Lighting"; > = 0.8;
uniform float Ks < string UIName = "Specular ks"; float UIMin = 0; float UIMax = 1; string UIGroup = "Lighting";
                   string UIHelp = "Peak of the thesis' highlight lobe, which is not normalised: the surface can reflect more light than falls on it (lit head-on, Kd = Ks = 1 and power 1: 1.67 with Phong, 1.91 with Blinn)"; > = 0.4;
uniform float Power < string UIName = "Specular power"; float UIMin = 1; float UIMax = 256; string UIGroup = "Lighting"; > = 32.0;
uniform bool Metal < string UIName = "Metal"; string UIGroup = "Lighting";
                     string UIHelp = "On: a metal, whose highlight takes the object's colour; off: a dielectric, whose highlight takes the light's colour"; > = false;


struct Geometry { float lambert; float phong; float blinn; };

// The lamp's factors: cos θ and the lobes for a point, their means over the disc for a sphere lamp
// (sphere_lamp.glsl), their integrals over a flat disc or rectangle (area_light.glsl). `lobes` false:
// the diffuse factor only (the lobes over a sized lamp cost a loop).
Geometry geometry(vec3 position, vec3 normal, bool lobes) {
    vec3 n = normalize(normal);
    vec3 l = normalize(LightPosition - position);
    vec3 v = normalize(CameraPosition - position);
    Geometry g = Geometry(0.0, 0.0, 0.0);
    if (flat_light()) {
        vec3 f = flat_light_factors(position, n, v, Power, lobes);
        return Geometry(f.x, f.y, f.z);
    }
    float sin_alpha = LightRadius > 0.0 ? min(LightRadius / length(LightPosition - position), 0.999) : 0.0;
    if (sin_alpha > 0.0) {
        g.lambert = sphere_lamp_lambert(dot(n, l), sin_alpha * sin_alpha);
        if (lobes) {
            vec2 both = sphere_lamp_lobes(n, v, l, sin_alpha, Power);
            g.phong = both.x;
            g.blinn = both.y;
        }
        return g;
    }
    g.lambert = max(dot(n, l), 0.0);
    g.phong = g.lambert > 0.0 ? pow(max(dot(reflect(-l, n), v), 0.0), Power) : 0.0;
    g.blinn = g.lambert > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), Power) : 0.0;
    return g;
}

// The environment's light on the surface as weights of its spectra: the diffuse part (times Kd, to be
// multiplied by the object's spectrum) and the highlight (times Ks); zero without a spectral form.
struct Surroundings { bool on; vec3 diffuse; vec3 highlight; };

// lobe: 0 none, 1 Phong, 2 Blinn.
Surroundings surroundings(vec3 position, vec3 normal, int lobe) {
    Surroundings s = Surroundings(spectral_environment(), vec3(0.0), vec3(0.0));
    if (!s.on) return s;
    vec3 n = normalize(normal), v = normalize(CameraPosition - position);
    s.diffuse = Kd * spectral_environment_irradiance(n);
    if (lobe != 0) s.highlight = Ks * spectral_environment_highlight(n, v, lobe == 2, Power);
    return s;
}

// The environment's radiance at `nm` as the surface returns it: (diffuse, highlight) before the object.
vec2 surroundings_at(Surroundings s, int nm) {
    vec3 spectra = spectral_environment_spectra(nm);
    return vec2(dot(s.diffuse, spectra), dot(s.highlight, spectra));
}

// Integrates I(l) = Brightness light(l) (object(l) diffuse + specular) + the surroundings over
// Lower..Upper in Steps (single fetch).
vec3 integrate(float diffuse, float specular, bool constant_spectra, Surroundings env) {
    vec3 lamp = vec3(0.0), surrounding = vec3(0.0);
    float ybar_sum = 0.0;
    for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
        vec3 cmf = cmf_at(nm);
        float light = constant_spectra ? 1.0 : spectrum_at(LightSpectrum, nm);
        float object = constant_spectra ? 1.0 : spectrum_at(ObjectSpectrum, nm);
        lamp += light * (object * diffuse + specular) * cmf;
        if (env.on) {
            vec2 e = surroundings_at(env, nm);
            surrounding += (object * e.x + e.y) * cmf;
        }
        ybar_sum += cmf.y;
    }
    return (lamp * Brightness + surrounding) * normalisation(ybar_sum);
}

GLSLShader ConstantFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, false);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, 0.0, true, Surroundings(false, vec3(0.0), vec3(0.0)))), 1.0);
        fx_capture();
    }
}

// The same result without hoisting: the geometry and k are recomputed for every wavelength.
GLSLShader ConstantUnoptimisedFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
            Geometry g = geometry(fs_in.world_position, fs_in.normal, false);
            vec3 cmf = cmf_at(nm);
            ybar_sum += cmf.y;
            xyz += Kd * g.lambert * cmf;
        }
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness), 1.0);
        fx_capture();
    }
}

GLSLShader LambertFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, false);
        Surroundings env = surroundings(fs_in.world_position, fs_in.normal, 0);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, 0.0, false, env)), 1.0);
        fx_capture();
    }
}

GLSLShader PhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, true);
        Surroundings env = surroundings(fs_in.world_position, fs_in.normal, 1);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, Ks * g.phong, false, env)), 1.0);
        fx_capture();
    }
}

GLSLShader BlinnFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, true);
        Surroundings env = surroundings(fs_in.world_position, fs_in.normal, 2);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, Ks * g.blinn, false, env)), 1.0);
        fx_capture();
    }
}

// Combined fetch (Code 9/10, eq. 57): one texel of each spectrum gives four wavelengths, the CMF
// block for them is a 4x4 matrix. Every nm in Lower..Upper is used (Steps does not apply).
// Returns the object-weighted and the light-only XYZ (for the metal switch), each normalised and times
// Brightness; and the surroundings' diffuse part (object-weighted), highlight, and highlight weighted
// by the object, normalised.
struct CombinedSums { vec3 object; vec3 light; vec3 env_body; vec3 env_highlight; vec3 env_highlight_object; };

CombinedSums integrate_combined(Surroundings env) {
    vec3 xyz_object = vec3(0.0), xyz_light = vec3(0.0), body = vec3(0.0), highlight = vec3(0.0), highlight_object = vec3(0.0);
    float ybar_sum = 0.0;
    int first = (Lower - kPackedFirstNm) / 4, last = (Upper - kPackedFirstNm) / 4;
    for (int t = first; t <= last; ++t) {
        vec4 light = spectrum_texel(LightSpectrum, t);
        vec4 object = spectrum_texel(ObjectSpectrum, t);
        int nm = kPackedFirstNm + 4 * t;
        // Wavelengths of the first and last texel outside Lower..Upper take no part.
        vec4 inside = vec4(greaterThanEqual(ivec4(nm) + ivec4(0, 1, 2, 3), ivec4(Lower))) *
                      vec4(lessThanEqual(ivec4(nm) + ivec4(0, 1, 2, 3), ivec4(Upper)));
        mat4x3 cmf = cmf_combined(t);
        xyz_object += cmf * (light * object * inside);
        xyz_light += cmf * (light * inside);
        ybar_sum += dot(vec4(cmf[0].y, cmf[1].y, cmf[2].y, cmf[3].y), inside);
        if (env.on) {
            vec4 diffuse, specular;
            for (int j = 0; j < 4; ++j) {
                vec2 e = inside[j] > 0.0 ? surroundings_at(env, nm + j) : vec2(0.0);
                diffuse[j] = e.x;
                specular[j] = e.y;
            }
            body += cmf * (object * diffuse);
            highlight += cmf * specular;
            highlight_object += cmf * (object * specular);
        }
    }
    float k = normalisation(ybar_sum);
    return CombinedSums(xyz_object * k * Brightness, xyz_light * k * Brightness, body * k, highlight * k, highlight_object * k);
}

GLSLShader CombinedFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, false);
        CombinedSums sums = integrate_combined(surroundings(fs_in.world_position, fs_in.normal, 0));
        color = vec4(xyz_to_srgb(sums.object * Kd * g.lambert + sums.env_body), 1.0);
        fx_capture();
    }
}

// Code 11's two branches, with the switch as the thesis' text (ch. 4.2, after eq. 32) and physics
// have it: a metal's highlight has the object's colour, RGB(xyz_obj * (lambert + spec)); a
// dielectric's the light's, RGB(xyz_obj * lambert) + RGB(xyz_light * spec). The listing itself
// runs them the other way round (its MetalObject picks the light-coloured one). The surroundings'
// diffuse part joins the body, their highlight the highlight.
GLSLShader CombinedPhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, true);
        CombinedSums sums = integrate_combined(surroundings(fs_in.world_position, fs_in.normal, 1));
        vec3 rgb = Metal ? xyz_to_srgb(sums.object * (Kd * g.lambert + Ks * g.phong) + sums.env_body + sums.env_highlight_object)
                         : xyz_to_srgb(sums.object * Kd * g.lambert + sums.env_body) + xyz_to_srgb(sums.light * Ks * g.phong + sums.env_highlight);
        color = vec4(rgb, 1.0);
        fx_capture();
    }
}

// Level of detail (ch. 4.6, Table 9): the CMFs and both spectra are fetched only at support points
// every 2^(9 - LodLevel) nm from Lower (Upper is the last one) and interpolated linearly for every nm
// in between; level 9 fetches every nm and equals Phong. `fxview spectra lod` measures each level's
// colour error. The environment's spectra are fetched at the support points too.
uniform int LodLevel < string UIName = "LOD level"; int UIMin = 1; int UIMax = 9; string UIGroup = "Integration"; int UIOrder = 5;
                       string UIHelp = "LodPhong: support points every 2^(9 - level) nm, linear in between"; > = 6;

struct Support { vec3 cmf; float light; float object; vec2 env; };
Support support_at(int nm, Surroundings env) {
    return Support(cmf_at(nm), spectrum_at(LightSpectrum, nm), spectrum_at(ObjectSpectrum, nm), env.on ? surroundings_at(env, nm) : vec2(0.0));
}

void add_interpolated(inout vec3 xyz, inout float ybar_sum, Support a, Support b, float t, float diffuse, float specular) {
    vec3 cmf = mix(a.cmf, b.cmf, t);
    float object = mix(a.object, b.object, t);
    vec2 env = mix(a.env, b.env, t);
    xyz += (mix(a.light, b.light, t) * (object * diffuse + specular) * Brightness + object * env.x + env.y) * cmf;
    ybar_sum += cmf.y;
}

GLSLShader LodPhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal, true);
        float diffuse = Kd * g.lambert, specular = Ks * g.phong;
        Surroundings env = surroundings(fs_in.world_position, fs_in.normal, 1);
        int spacing = 1 << (9 - clamp(LodLevel, 1, 9));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        for (int a = Lower; a < Upper; a += spacing) {
            int b = min(a + spacing, Upper);
            Support sa = support_at(a, env), sb = support_at(b, env);
            for (int nm = a; nm < b; ++nm) add_interpolated(xyz, ybar_sum, sa, sb, float(nm - a) / float(b - a), diffuse, specular);
        }
        Support last = support_at(Upper, env);
        add_interpolated(xyz, ybar_sum, last, last, 0.0, diffuse, specular);
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum)), 1.0);
        fx_capture();
    }
}

technique Constant { pass p0 { VertexShader = StandardVS; FragmentShader = ConstantFS; } }
technique ConstantUnoptimised { pass p0 { VertexShader = StandardVS; FragmentShader = ConstantUnoptimisedFS; } }
technique Lambert { pass p0 { VertexShader = StandardVS; FragmentShader = LambertFS; } }
technique Phong < bool Default = true; > { pass p0 { VertexShader = StandardVS; FragmentShader = PhongFS; } }
technique Blinn { pass p0 { VertexShader = StandardVS; FragmentShader = BlinnFS; } }
technique Single { pass p0 { VertexShader = StandardVS; FragmentShader = LambertFS; } }
technique Combined { pass p0 { VertexShader = StandardVS; FragmentShader = CombinedFS; } }
technique CombinedPhong { pass p0 { VertexShader = StandardVS; FragmentShader = CombinedPhongFS; } }
technique LodPhong { pass p0 { VertexShader = StandardVS; FragmentShader = LodPhongFS; } }
