// cd.fx's Orders technique: the grating's orders under the scene's light (a point, a sphere, a flat
// disc or rectangle) and under the spectral environment, and the per-frame table they read. Needs
// cd.fx's parameters and Disc; docs/diffraction.md. CPU twin: viewer/reference/cd_reference.cpp.
#pragma once

// What is the same at every pixel is computed once a frame by a small pass (OrdersTableFS) into
// OrdersTable, and read from there instead of fetching spectra per nm at every pixel:
// row 0  texel k: S x̄ȳz̄ at sample k (S the light spectrum), w: ȳ;
// rows 1-3 texel b: Σ S x̄ȳz̄ j^n over the samples j of lamp band b (LampBand nm), n = 0, 1, 2;
// row 4  texel 0: the coating's Σ S R x̄ȳz̄ over all samples, w: Σ ȳ;
// rows 5-7 texel b: Σ S_k x̄, Σ S_k ȳ, Σ S_k z̄ (k = the environment's three spectra) over environment
//        band b (EnvironmentBand nm), w: the band's mean wavelength;
// row 8  texel m: x the order weight sinc²(π m PitFraction) (m > 0), y their sum over 1..m.
// 471 samples at most (360-830 nm at 1 nm).
texture OrdersTableTarget : RENDERCOLORTARGET < int2 Dimensions = {512, 9}; string Format = "32F"; >;
uniform sampler2D OrdersTable = sampler_state { Texture = <OrdersTableTarget>; Filter = Nearest; };

vec3 light_cmf(int k) { return texelFetch(OrdersTable, ivec2(k, 0), 0).xyz; }
vec3 lamp_band_moment(int band, int n) { return texelFetch(OrdersTable, ivec2(band, 1 + n), 0).xyz; }
vec4 coating_sums() { return texelFetch(OrdersTable, ivec2(0, 4), 0); }
vec4 environment_band(int band, int channel) { return texelFetch(OrdersTable, ivec2(band, 5 + channel), 0); }
// The orders' weights and shares, copied from row 8 by the fragments that need them (load_order_weights): the
// orders read them several times per band, faster from registers than from the table.
float order_weights[33], order_shares_upto[33];
void load_order_weights() {
    for (int m = 0; m <= 32; ++m) {
        vec2 entry = texelFetch(OrdersTable, ivec2(m, 8), 0).xy;
        order_weights[m] = entry.x;
        order_shares_upto[m] = entry.y;
    }
}
float order_weight(int m) { return order_weights[m]; }
float order_share(int m) { return order_shares_upto[m]; }

// Orders past 32 are not drawn: with d up to 5000 nm, light of 360 nm has no more than 28.
const int kMaxOrder = 32;

// The propagating orders first..last for d / λ = orders_per_unit: |m λ/d - v_x|² + v_y² < 1.
ivec2 propagating_orders(vec3 view, float orders_per_unit) {
    float reach = sqrt(max(1.0 - view.y * view.y, 0.0));
    return ivec2(clamp(int(floor((view.x - reach) * orders_per_unit)) + 1, -kMaxOrder, 0),
                 clamp(int(ceil((view.x + reach) * orders_per_unit)) - 1, 0, kMaxOrder));
}

// Order m's efficiency: the mirror's share, or the rest in proportion to sinc²; `others` the
// propagating orders' summed weights (0: the mirror alone takes everything).
float order_efficiency(int m, float others) {
    return m == 0 ? (others > 0.0 ? ZeroOrder : 1.0) : (1.0 - ZeroOrder) * order_weight(abs(m)) / others;
}

// The scene's lamp through the orders at wavelength nm: every order whose direction can fall on the
// light (|l_x - c_x| <= |l - c|), looked up.
float lamp_radiance(bool flat_lamp, bool disc, Disc d, FlatLightView flat_view, vec3 view, vec3 light, float edge, float view_spread, float turn_spread,
                    int nm) {
    float tracks = float(max(Tracks, 1)), spacing = max(TrackSpacing, 1.0);
    float ratio = float(nm) / spacing, orders_per_unit = spacing / float(nm);  // λ / d and d / λ
    ivec2 orders = propagating_orders(view, orders_per_unit);
    int first = orders.x, last = orders.y;
    float others = order_share(-first) + order_share(last);
    float widest = ratio / tracks + view_spread + float(max(-first, last)) * ratio * turn_spread;
    float near = edge + 0.5 * widest;
    int from = max(first, int(ceil((view.x + light.x - near) * orders_per_unit)));
    int to = min(last, int(floor((view.x + light.x + near) * orders_per_unit)));
    float radiance = 0.0;
    for (int m = from; m <= to; ++m) {
        vec2 tangential = vec2(float(m) * ratio - view.x, -view.y);
        float z2 = 1.0 - dot(tangential, tangential);
        if (z2 <= 0.0) continue;
        vec3 incidence = tangential.x * d.across + tangential.y * d.along + sqrt(z2) * d.n;
        float width = ratio / tracks + view_spread + float(abs(m)) * ratio * turn_spread;
        float efficiency = order_efficiency(m, others);
        radiance += efficiency * (flat_lamp ? flat_light_radiance(flat_view, incidence, width, disc) : sphere_light_radiance(length(incidence - d.l), edge, width));
    }
    return radiance;
}

// Order m at the wavelength of `ratio` = λ / d (`others`: the propagating orders' summed weights there)
// as a band records it: x the ramp's value 0.5 + angle / width (the angle from the light's outline,
// inside positive, -4 where the order misses), y the height of its direction above the disc, z its
// radiance inside (efficiency included), w 1 where the order propagates.
vec4 lamp_order_record(bool flat_lamp, bool disc, Disc d, FlatLightView flat_view, vec3 view, float edge, float view_spread, float turn_spread,
                       int m, float ratio, float others) {
    float width = ratio / float(max(Tracks, 1)) + view_spread + float(abs(m)) * ratio * turn_spread;
    vec2 tangential = vec2(float(m) * ratio - view.x, -view.y);
    float z2 = 1.0 - dot(tangential, tangential);
    if (z2 <= 0.0) return vec4(0.5 - 4.0 / width, 0.0, 0.0, 0.0);
    float rise = sqrt(z2);
    float efficiency = order_efficiency(m, others);
    vec3 incidence = tangential.x * d.across + tangential.y * d.along + rise * d.n;
    if (flat_lamp) return vec4(0.5 + max(flat_light_angle(flat_view, incidence, disc), -4.0) / width, rise, efficiency * flat_light_ramp_scale(flat_view, width, disc), 1.0);
    return vec4(0.5 + max(edge - length(incidence - d.l), -4.0) / width, rise, efficiency * sphere_light_ramp_scale(edge, width), 1.0);
}

// The propagating orders' summed weights at λ / d = ratio.
float order_shares(vec3 view, float ratio) {
    ivec2 orders = propagating_orders(view, 1.0 / ratio);
    return order_share(-orders.x) + order_share(orders.y);
}

// Under a light much larger than the orders' blur and than a band's step, each order near the light
// is recorded at both ends of a band of LampBand nm, and its ramp u (0.5 + angle / width, smooth in λ)
// and its radiance inside s are followed linearly between: its radiance at the band's sample j is
// (s_a + j ds) clamp(u_a + j du, 0, 1). Near the horizon (its direction less than kLowOrder above the
// disc, where it turns fast with λ, or where it starts or stops propagating) a record at the band's
// middle checks that: where the ramp or the radiance there is off the line by more than 0.02, the
// order is followed through both halves of the band. Where the clamp does not act within the band
// (the order inside, outside or on the ramp throughout) its sum is a combination of the band's
// moments Σ S x̄ȳz̄ j^n (n = 0, 1, 2, from OrdersTable); two orders that cross the light's edge in the
// band are summed in one pass over its samples, any further one in a pass of its own. (Orders
// outside, bands inside, so that a band's end serves as the next band's start, cost llvmpipe 1.5-2x
// more: each order then runs through every band; so did keeping that end in an array per order.)
const float kLowOrder = 0.25;  // sin 14.5°

void lamp_orders_banded(bool flat_lamp, bool disc, Disc d, FlatLightView flat_view, vec3 view, vec3 light, float edge, float view_spread, float turn_spread,
                        int most, float lowest_rise, inout vec3 lamp) {
    float tracks = float(max(Tracks, 1)), spacing = max(TrackSpacing, 1.0), centre = view.x + light.x;
    int step = max(Steps, 1), last_sample = max(Upper - Lower, 0) / step, per_band = max(LampBand / step, 1);
    int k0 = 0;
    do {
        int k1 = min(k0 + per_band, last_sample), end = k1 == last_sample ? k1 : k1 - 1;
        float span = float(max(k1 - k0, 1));
        float ra = float(Lower + k0 * step) / spacing, rb = float(Lower + k1 * step) / spacing, rm = 0.5 * (ra + rb);
        float near = edge + 0.5 * (rb / tracks + view_spread + float(most) * rb * turn_spread);
        float low = centre - near, high = centre + near;
        // An order whose direction stays lower above the disc than the light's lowest direction, by
        // more than half its width, misses the light (a chord exceeds the heights' difference): the
        // loop skips it. Under a light reaching far to the side this halves the orders visited.
        float sink = lowest_rise - (near - edge);
        if (sink > 0.0) {
            float reach_above = sqrt(max(1.0 - sink * sink - view.y * view.y, 0.0));
            low = max(low, view.x - reach_above);
            high = min(high, view.x + reach_above);
        }
        int from = max(int(ceil(min(low / ra, low / rb))), -kMaxOrder), to = min(int(floor(max(high / ra, high / rb))), kMaxOrder);
        float others_a = order_shares(view, ra), others_b = order_shares(view, rb), others_m = order_shares(view, rm);
        vec3 along = vec3(0.0);                         // coefficients of the moments 0, 1, 2
        vec4 crossing0 = vec4(0.0), crossing1 = vec4(0.0);  // u_a, du, s_a, ds of two orders crossing the edge
        int crossings = 0;
        int m = from;
        if (from <= to) do {
            vec4 a = lamp_order_record(flat_lamp, disc, d, flat_view, view, edge, view_spread, turn_spread, m, ra, others_a);
            vec4 b = lamp_order_record(flat_lamp, disc, d, flat_view, view, edge, view_spread, turn_spread, m, rb, others_b);
            if (a.w == 0.0 && b.w == 0.0) continue;  // evanescent at both ends
            vec4 middle = vec4(0.0);
            bool linear = true;
            if (min(a.y, b.y) < kLowOrder) {  // near the horizon (or not propagating at an end): checked at the middle
                middle = lamp_order_record(flat_lamp, disc, d, flat_view, view, edge, view_spread, turn_spread, m, rm, others_m);
                linear = a.w == b.w && middle.w == a.w && abs(clamp(middle.x, 0.0, 1.0) - clamp(0.5 * (a.x + b.x), 0.0, 1.0)) <= 0.02 &&
                         abs(middle.z - 0.5 * (a.z + b.z)) <= 0.02 * max(a.z, b.z);
            }
            if (a.w == 0.0) a.x = b.x;  // an order that stops propagating in the band fades out
            if (b.w == 0.0) b.x = a.x;
            if (!linear) {  // followed through both halves of the band
                if (middle.w == 0.0) middle.x = 0.5 * (a.x + b.x);
                for (int k = k0; k <= end; ++k) {
                    float t = float(k - k0) / span;
                    vec2 ramp_scale = t < 0.5 ? mix(a.xz, middle.xz, 2.0 * t) : mix(middle.xz, b.xz, 2.0 * t - 1.0);
                    lamp += (ramp_scale.y * clamp(ramp_scale.x, 0.0, 1.0)) * light_cmf(k);
                }
                continue;
            }
            float du = (b.x - a.x) / span, ds = (b.z - a.z) / span, lowest = min(a.x, b.x), highest = max(a.x, b.x);
            if (highest <= 0.0) continue;
            if (lowest >= 1.0) {
                along += vec3(a.z, ds, 0.0);
            } else if (lowest >= 0.0 && highest <= 1.0) {
                along += vec3(a.z * a.x, a.z * du + ds * a.x, ds * du);
            } else if (crossings == 0) {
                crossing0 = vec4(a.x, du, a.z, ds);
                crossings = 1;
            } else if (crossings == 1) {
                crossing1 = vec4(a.x, du, a.z, ds);
                crossings = 2;
            } else {
                for (int k = k0; k <= end; ++k) {
                    float j = float(k - k0);
                    lamp += ((a.z + j * ds) * clamp(a.x + j * du, 0.0, 1.0)) * light_cmf(k);
                }
            }
        } while (++m <= to);
        // The two orders crossing the light's edge in one pass over the samples, the others from the
        // band's moments.
        int k = k0;
        if (crossings > 0) do {
            float j = float(k - k0);
            lamp += light_cmf(k) * ((crossing0.z + j * crossing0.w) * clamp(crossing0.x + j * crossing0.y, 0.0, 1.0) +
                                    (crossing1.z + j * crossing1.w) * clamp(crossing1.x + j * crossing1.y, 0.0, 1.0));
        } while (++k <= end);
        int band = k0 / per_band;
        lamp += along.x * lamp_band_moment(band, 0) + along.y * lamp_band_moment(band, 1) + along.z * lamp_band_moment(band, 2);
        if (end == last_sample) break;  // a last band that ends on the last sample has taken it
        k0 += per_band;
    } while (k0 <= last_sample);
}

// The scene's lamp through the orders at every sampled nm: Σ S x̄ȳz̄ Σ_m efficiency · ramp, into `lamp`. `flat_lamp` and
// `disc` are constants at each call, so that each call compiles to its own light's code: llvmpipe
// runs both sides of a branch inside a loop.
void lamp_orders(bool flat_lamp, bool disc, Disc d, FlatLightView flat_view, vec3 view, vec3 light, float edge, float view_spread, float turn_spread,
                 inout vec3 lamp) {
    float tracks = float(max(Tracks, 1)), reach = sqrt(max(1.0 - view.y * view.y, 0.0)), spacing = max(TrackSpacing, 1.0);
    // Every order leaves with the along-track component -v_y: none meets the light unless that lies
    // within `near` of the light's l_y (|l_y - c_y| <= |l - c|) for the widest order at the longest
    // wavelength. Most pixels lie outside that sector and skip the orders.
    float longest = float(Upper) / spacing;
    int most = min(int(ceil((abs(view.x) + reach) * spacing / float(max(Lower, 1)))), kMaxOrder);
    float widest = longest / tracks + view_spread + float(most) * longest * turn_spread;
    bool lit = view.z > 0.0 && abs(view.y + light.y) <= edge + 0.5 * widest;
    if (!lit) return;
    load_order_weights();
    // A light twice the orders' blur and a band's step: its edge followed through bands.
    float size = flat_lamp ? min(flat_view.half_angles.x, flat_view.half_angles.y) : edge;
    int per_band = max(LampBand / max(Steps, 1), 1);
    if (per_band > 1 && size > 2.0 * max(widest, float(most * per_band * max(Steps, 1)) / spacing)) {
        // How high above the disc the light's lowest direction is (a chord bounds a sphere's heights).
        float lowest_rise = flat_lamp ? flat_light_lowest_height(flat_view, d.n, disc) : light.z - edge;
        lamp_orders_banded(flat_lamp, disc, d, flat_view, view, light, edge, view_spread, turn_spread, most, lowest_rise, lamp);
        return;
    }
    int step = max(Steps, 1), last_sample = max(Upper - Lower, 0) / step;
    for (int k = 0; k <= last_sample; ++k)
        lamp += light_cmf(k) * lamp_radiance(flat_lamp, disc, d, flat_view, view, light, edge, view_spread, turn_spread, Lower + k * step);
}

// The surroundings: every propagating order mirrors the environment's spectral radiance
// L = Σ_k w_k S_k from the direction the grating equation picks for it. The direction moves slowly
// with λ, so it is found once per band of EnvironmentBand nm, at the band's mean wavelength, against
// the band's sums of S_k × CMF. The orders' widths are not applied: the sky and the studio are smooth
// at their scale. Σ efficiency × (x, y, z) per unit Reflectance.
vec3 environment_orders(Disc d, vec3 view) {
    load_order_weights();
    vec3 xyz = vec3(0.0);
    float spacing = max(TrackSpacing, 1.0);
    int step = max(Steps, 1), per_band = max(EnvironmentBand / step, 1);
    for (int band = 0; Lower + band * per_band * step <= Upper; ++band) {
        vec4 band_x = environment_band(band, 0), band_y = environment_band(band, 1), band_z = environment_band(band, 2);
        float ratio = band_x.w / spacing;
        ivec2 orders = propagating_orders(view, 1.0 / ratio);
        float others = order_share(-orders.x) + order_share(orders.y);
        for (int m = orders.x; m <= orders.y; ++m) {
            vec2 tangential = vec2(float(m) * ratio - view.x, -view.y);
            float z2 = 1.0 - dot(tangential, tangential);
            if (z2 <= 0.0) continue;
            vec3 w = spectral_environment_weights(tangential.x * d.across + tangential.y * d.along + sqrt(z2) * d.n);
            xyz += order_efficiency(m, others) * vec3(dot(w, band_x.xyz), dot(w, band_y.xyz), dot(w, band_z.xyz));
        }
    }
    return xyz;
}

// Fills OrdersTable (see there).
GLSLShader OrdersTableFS {
    layout(location = 0) out vec4 entry;
    void main() {
        ivec2 texel = ivec2(gl_FragCoord.xy);
        int step = max(Steps, 1), last_sample = max(Upper - Lower, 0) / step;
        int per_band = max(LampBand / step, 1), per_environment_band = max(EnvironmentBand / step, 1);
        entry = vec4(0.0);
        if (texel.y == 0 && texel.x <= last_sample) {
            int nm = Lower + texel.x * step;
            vec3 cmf = cmf_at(nm);
            entry = vec4(spectrum_at(LightSpectrum, nm) * cmf, cmf.y);
        } else if (texel.y >= 1 && texel.y <= 3 && texel.x * per_band <= last_sample) {
            int k0 = texel.x * per_band, k1 = min(k0 + per_band, last_sample), end = k1 == last_sample ? k1 : k1 - 1;
            for (int k = k0; k <= end; ++k) {
                int nm = Lower + k * step;
                float j = float(k - k0), power = texel.y == 1 ? 1.0 : (texel.y == 2 ? j : j * j);
                entry.xyz += spectrum_at(LightSpectrum, nm) * cmf_at(nm) * power;
            }
        } else if (texel.y == 4 && texel.x == 0) {
            for (int k = 0; k <= last_sample; ++k) {
                int nm = Lower + k * step;
                vec3 cmf = cmf_at(nm);
                entry += vec4(spectrum_at(LightSpectrum, nm) * spectrum_at(SubstrateSpectrum, nm) * cmf, cmf.y);
            }
        } else if (texel.y >= 5 && texel.y <= 7 && Lower + texel.x * per_environment_band * step <= Upper) {
            float nm_sum = 0.0, count = 0.0;
            for (int i = 0; i < per_environment_band; ++i) {
                int nm = Lower + (texel.x * per_environment_band + i) * step;
                if (nm > Upper) break;
                entry.xyz += spectral_environment_spectra(nm) * cmf_at(nm)[texel.y - 5];
                nm_sum += float(nm);
                count += 1.0;
            }
            entry.w = nm_sum / count;
        } else if (texel.y == 8 && texel.x <= kMaxOrder) {
            for (int m = 1; m <= texel.x; ++m) {
                float a = 3.14159265358979323846 * float(m) * PitFraction;
                float sinc = sin(a) / a;
                entry.x = sinc * sinc;
                entry.y += entry.x;
            }
        }
    }
}
