// Diffraction by the tracks of a CD or DVD, a reflection grating (DOMAIN.md §4; seed 002 eq. 36-41,
// 70-72). x = d · u / λ is the path difference between neighbouring tracks in wavelengths, with d the
// track spacing and u = (l + v) · g the sum of the light and view directions' components along the
// grating vector g (in the surface, across the tracks); orders m appear where x = m.
#pragma once

namespace fxview::optics {

// Fraunhofer interference of N equally spaced tracks, normalised to 1 at the orders:
// (sin(Nπx) / (N sin(πx)))². The closed form of the geometric series of phasors.
double grating_intensity(double x, int tracks);
// The same as an explicit sum of N unit phasors, |Σ exp(2πi k x)|² / N²: an independent evaluation.
double grating_intensity_phasors(double x, int tracks);

namespace thesis {
// Eq. 72 with the thesis' simplifications: the track spacing grows linearly from d (light across the
// tracks) to 3d (along them) with influence = abs(G·L); I = frac(d_eff · abs(cosθcam − cosθlight) / λ),
// cut to 0 below `threshold`. Also returns frac's argument.
struct CdIntensity {
    double intensity;
    double cycles;
    double spacing_nm;
};
CdIntensity cd_intensity(double spacing_nm, double influence, double cos_view, double cos_light, double wavelength_nm,
                         double threshold);
}  // namespace thesis

}  // namespace fxview::optics
