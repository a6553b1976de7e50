// Wavelength-based lighting of seed 002 (ch. 4.2-4.3, Tables 3 and 4): light and object spectra
// multiplied per wavelength (eq. 56), shaded, and integrated against the CIE colour matching
// functions in the fragment shader; XYZ -> linear sRGB by eq. 9. Every technique has a CPU
// reference (viewer/reference/spectral_reference.cpp) that `fxview compare` checks it against.
#include "standard.glsl"
#include "spectral.glsl"

// Indices into spectra/library.txt (`fxview spectra list`).
uniform int LightSpectrum < string UIName = "Light spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                            string UIHelp = "Index in spectra/library.txt (5 = D65)"; > = 5;
uniform int ObjectSpectrum < string UIName = "Object spectrum"; string UIWidget = "combo"; string UIItems = "spectral:library"; string UIGroup = "Spectra";
                             string UIHelp = "Index in spectra/library.txt (10-23 = CIE test colour samples)"; > = 14;
uniform float Brightness < string UIName = "Brightness"; float UIMin = 0; float UIMax = 8; float UIStep = 0.1; string UIGroup = "Lighting";
                           string UIHelp = "Intensity scale of the lit colour"; > = 2.0;
uniform float Kd < string UIName = "Diffuse kd"; float UIMin = 0; float UIMax = 1; string UIGroup = "Lighting"; > = 0.8;
uniform float Ks < string UIName = "Specular ks"; float UIMin = 0; float UIMax = 1; string UIGroup = "Lighting";
                   string UIHelp = "Peak of the thesis' highlight lobe, which is not normalised: the surface can reflect more light than falls on it (lit head-on, Kd = Ks = 1 and power 1: 1.67 with Phong, 1.91 with Blinn)"; > = 0.4;
uniform float Power < string UIName = "Specular power"; float UIMin = 1; float UIMax = 256; string UIGroup = "Lighting"; > = 32.0;
uniform bool Metal < string UIName = "Metal"; string UIGroup = "Lighting";
                     string UIHelp = "On: a metal, whose highlight takes the object's colour; off: a dielectric, whose highlight takes the light's colour"; > = false;

struct Geometry { float lambert; float phong; float blinn; };

Geometry geometry(vec3 position, vec3 normal) {
    vec3 n = normalize(normal);
    vec3 l = normalize(LightPosition - position);
    vec3 v = normalize(CameraPosition - position);
    Geometry g;
    g.lambert = max(dot(n, l), 0.0);
    g.phong = g.lambert > 0.0 ? pow(max(dot(reflect(-l, n), v), 0.0), Power) : 0.0;
    g.blinn = g.lambert > 0.0 ? pow(max(dot(n, normalize(l + v)), 0.0), Power) : 0.0;
    return g;
}

// Integrates I(l) = light(l) * (object(l) * diffuse + specular) over Lower..Upper in Steps (single fetch).
vec3 integrate(float diffuse, float specular, bool constant_spectra) {
    vec3 xyz = vec3(0.0);
    float ybar_sum = 0.0;
    for (int nm = Lower; nm <= Upper; nm += max(Steps, 1)) {
        vec3 cmf = cmf_at(nm);
        float light = constant_spectra ? 1.0 : spectrum_at(LightSpectrum, nm);
        float object = constant_spectra ? 1.0 : spectrum_at(ObjectSpectrum, nm);
        xyz += light * (object * diffuse + specular) * cmf;
        ybar_sum += cmf.y;
    }
    return xyz * normalisation(ybar_sum) * Brightness;
}

GLSLShader ConstantFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, 0.0, true)), 1.0);
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
            Geometry g = geometry(fs_in.world_position, fs_in.normal);
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
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, 0.0, false)), 1.0);
        fx_capture();
    }
}

GLSLShader PhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, Ks * g.phong, false)), 1.0);
        fx_capture();
    }
}

GLSLShader BlinnFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        color = vec4(xyz_to_srgb(integrate(Kd * g.lambert, Ks * g.blinn, false)), 1.0);
        fx_capture();
    }
}

// Combined fetch (Code 9/10, eq. 57): one texel of each spectrum gives four wavelengths, the CMF
// block for them is a 4x4 matrix. Every nm in Lower..Upper is used (Steps does not apply).
// Returns the object-weighted and the light-only XYZ (for the metal switch), each normalised.
void integrate_combined(out vec3 xyz_object, out vec3 xyz_light) {
    xyz_object = vec3(0.0);
    xyz_light = vec3(0.0);
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
    }
    float k = normalisation(ybar_sum) * Brightness;
    xyz_object *= k;
    xyz_light *= k;
}

GLSLShader CombinedFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        vec3 xyz_object, xyz_light;
        integrate_combined(xyz_object, xyz_light);
        color = vec4(xyz_to_srgb(xyz_object * Kd * g.lambert), 1.0);
        fx_capture();
    }
}

// Code 11's two branches, with the switch as the thesis' text (ch. 4.2, after eq. 32) and physics
// have it: a metal's highlight has the object's colour, RGB(xyz_obj * (lambert + spec)); a
// dielectric's the light's, RGB(xyz_obj * lambert) + RGB(xyz_light * spec). The listing itself
// runs them the other way round (its MetalObject picks the light-coloured one).
GLSLShader CombinedPhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        vec3 xyz_object, xyz_light;
        integrate_combined(xyz_object, xyz_light);
        vec3 rgb = Metal ? xyz_to_srgb(xyz_object * (Kd * g.lambert + Ks * g.phong))
                         : xyz_to_srgb(xyz_object * Kd * g.lambert) + xyz_to_srgb(xyz_light * Ks * g.phong);
        color = vec4(rgb, 1.0);
        fx_capture();
    }
}

// Level of detail (ch. 4.6, Table 9): the CMFs and both spectra are fetched only at support points
// every 2^(9 - LodLevel) nm from Lower (Upper is the last one) and interpolated linearly for every nm
// in between; level 9 fetches every nm and equals Phong. `fxview spectra lod` measures each level's
// colour error.
uniform int LodLevel < string UIName = "LOD level"; int UIMin = 1; int UIMax = 9; string UIGroup = "Integration"; int UIOrder = 5;
                       string UIHelp = "LodPhong: support points every 2^(9 - level) nm, linear in between"; > = 6;

struct Support { vec3 cmf; float light; float object; };
Support support_at(int nm) { return Support(cmf_at(nm), spectrum_at(LightSpectrum, nm), spectrum_at(ObjectSpectrum, nm)); }

void add_interpolated(inout vec3 xyz, inout float ybar_sum, Support a, Support b, float t, float diffuse, float specular) {
    vec3 cmf = mix(a.cmf, b.cmf, t);
    xyz += mix(a.light, b.light, t) * (mix(a.object, b.object, t) * diffuse + specular) * cmf;
    ybar_sum += cmf.y;
}

GLSLShader LodPhongFS {
    #include "fragment_inputs.glsl"
    #include "capture.glsl"
    layout(location = 0) out vec4 color;
    void main() {
        Geometry g = geometry(fs_in.world_position, fs_in.normal);
        float diffuse = Kd * g.lambert, specular = Ks * g.phong;
        int spacing = 1 << (9 - clamp(LodLevel, 1, 9));
        vec3 xyz = vec3(0.0);
        float ybar_sum = 0.0;
        for (int a = Lower; a < Upper; a += spacing) {
            int b = min(a + spacing, Upper);
            Support sa = support_at(a), sb = support_at(b);
            for (int nm = a; nm < b; ++nm) add_interpolated(xyz, ybar_sum, sa, sb, float(nm - a) / float(b - a), diffuse, specular);
        }
        Support last = support_at(Upper);
        add_interpolated(xyz, ybar_sum, last, last, 0.0, diffuse, specular);
        color = vec4(xyz_to_srgb(xyz * normalisation(ybar_sum) * Brightness), 1.0);
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
