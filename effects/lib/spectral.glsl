// Wavelength-based lighting (seed 002 ch. 4.2, 4.3; DOMAIN.md §2): the CMF and spectrum textures
// that fxview generates from spectra/library.txt and colord-data, the integration parameters, and
// the conversion XYZ -> linear sRGB (eq. 9) with the three gamut mappings.
#pragma once

// CMF texture: one texel per nm 360..830; row 0 CIE 1931 2°, row 1 CIE 1964 10°. Fetched
// unfiltered (Code 4). The 8-bit copy is the thesis' byte texture (Table 2), scaled by the zbar peak.
uniform sampler2D CmfFloat < string ResourceName = "spectral:cmf"; string Format = "32F";
                             string Filter = "nearest"; string Wrap = "clamp"; >;
uniform sampler2D CmfBytes < string ResourceName = "spectral:cmf"; string Format = "8";
                             string Filter = "nearest"; string Wrap = "clamp"; >;
// Packed spectra (fig. 19): 512 samples 324..835 nm, four per texel, 128 texels per spectrum,
// spectrum s at texel 128 * (s % 8) of row s / 8.
uniform sampler2D Spectra < string ResourceName = "spectral:library"; string Format = "32F";
                            string Filter = "nearest"; string Wrap = "clamp"; >;

uniform int Observer < string UIName = "Observer"; string UIWidget = "combo"; string UIItems = "CIE 1931 2°|CIE 1964 10°";
                       string UIGroup = "Colorimetry"; int UIOrder = 1; > = 0;
uniform bool ByteCmf < string UIName = "8-bit CMF texture"; string UIGroup = "Colorimetry"; int UIOrder = 2;
                       string UIHelp = "Byte storage of the tables: faster on old GPUs, less precise"; > = false;
uniform int Lower < string UIName = "Lower wavelength"; int UIMin = 360; int UIMax = 830; string UIUnits = "nm";
                    string UIGroup = "Integration"; int UIOrder = 1; > = 360;
uniform int Upper < string UIName = "Upper wavelength"; int UIMin = 360; int UIMax = 830; string UIUnits = "nm"; string UIAtLeast = "Lower";
                    string UIGroup = "Integration"; int UIOrder = 2; > = 830;
uniform int Steps < string UIName = "Steps"; int UIMin = 1; int UIMax = 50; string UIUnits = "nm";
                    string UIGroup = "Integration"; int UIOrder = 3;
                    string UIHelp = "Wavelength step in nm: the simplest level of detail"; > = 1;
uniform float K < string UIName = "k"; float UIMin = 0; float UIMax = 1; float UIStep = 0.0001; string UIGroup = "Integration";
                  int UIOrder = 4; string UIHelp = "Normalisation; 0 derives k = 1 / sum(ybar) so that a constant 1 gives Y = 1"; > = 0.0;
uniform int OutputMode < string UIName = "Out of gamut"; string UIWidget = "combo"; string UIItems = "clip|desaturate|scale|unbounded";
                         string UIGroup = "Colorimetry"; int UIOrder = 3;
                         string UIHelp = "clip: to [0, 1] (the thesis' 8-bit output); desaturate towards grey until no channel is negative; scale so the largest channel is 1; unbounded: negatives to 0, brightness kept (scene-referred: a light in lux or lumens sets it, leave the rest to exposure and tone mapping)";
                         string SceneLight = "output-range"; > = 0;

const int kPackedFirstNm = 324;

vec3 cmf_at(int nm) {
    ivec2 texel = ivec2(nm - 360, Observer);
    return ByteCmf ? texelFetch(CmfBytes, texel, 0).rgb : texelFetch(CmfFloat, texel, 0).rgb;
}

// Single fetch: one channel of one texel per wavelength.
float spectrum_at(int index, int nm) {
    int i = nm - kPackedFirstNm;
    ivec2 texel = ivec2(128 * (index % 8) + i / 4, index / 8);
    return texelFetch(Spectra, texel, 0)[i % 4];
}

// Combined fetch: the texel holding wavelengths 324 + 4 * t .. 324 + 4 * t + 3.
vec4 spectrum_texel(int index, int t) {
    return texelFetch(Spectra, ivec2(128 * (index % 8) + t, index / 8), 0);
}

// The 4x4 CMF block for the four wavelengths of texel t (eq. 57): columns are wavelengths.
mat4x3 cmf_combined(int t) {
    int nm = kPackedFirstNm + 4 * t;
    return mat4x3(cmf_at(nm), cmf_at(nm + 1), cmf_at(nm + 2), cmf_at(nm + 3));
}

// k of DOMAIN.md §2 for the sampled wavelengths: the user's value, or 1 / sum ybar.
float normalisation(float ybar_sum) { return K > 0.0 ? K : 1.0 / ybar_sum; }

vec3 xyz_to_srgb(vec3 xyz) {
    // Eq. 9 (GLSL matrices are column-major: the rows of eq. 9 are the columns below).
    mat3 m = mat3(3.240479, -0.969256, 0.055648,
                  -1.537150, 1.875992, -0.204043,
                  -0.498535, 0.041556, 1.057311);
    vec3 rgb = m * xyz;
    if (OutputMode == 1) {  // desaturate towards the grey of equal luminance until no channel is negative
        float grey = max(xyz.y, 0.0);
        float lowest = min(rgb.r, min(rgb.g, rgb.b));
        if (lowest < 0.0 && grey > 0.0) rgb = grey + (grey / (grey - lowest)) * (rgb - grey);
    } else if (OutputMode == 2) {  // uniform scaling so that the largest channel is 1
        rgb = max(rgb, 0.0);
        float highest = max(rgb.r, max(rgb.g, rgb.b));
        if (highest > 1.0) rgb /= highest;
    }
    return OutputMode == 3 ? max(rgb, 0.0) : clamp(rgb, 0.0, 1.0);
}
