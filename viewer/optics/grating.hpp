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

// A grating of N tracks lit over a square patch (N tracks across, N·d along them): the along-track
// phase y = d (l + v)·t / λ (t along the tracks) adds the factor sinc²(N y) of a uniformly lit
// straight segment, sinc(z) = sin(πz)/(πz), so the zero order is a highlight where l + v is parallel
// to n. A pixel sees a range of x and y; these average the intensity over the box [x ± wx/2] ×
// [y ± wy/2] (the pixel's extents in those coordinates), so that an order narrower than a pixel still
// adds its share. The box average of (sin(Nπx)/(N sin πx))² · sinc²(Ny) factors into:
//
// the average of the N-track term over [x ± w/2], from its Fourier series (the Fejér kernel)
// (1/N²)[N + 2 Σ_{k<N} (N−k) cos(2πkx) sinc(kw)];
double tracks_box_average(double x, double width, int tracks);
// the average of sinc²(N y) over [y ± w/2], from the sine integral:
// ∫ sinc²(z) dz = (Si(2πz) − sin²(πz)/(πz)) / π.
double patch_box_average(double y, double width, int tracks);
// The same two averages by another method: Gauss-Legendre quadrature (8 nodes per piece of at most
// half a fringe) of the explicit phasor sum across the tracks and of the along-track segment's
// amplitude; whole periods of the N-track term add 1/N each (Parseval).
double tracks_box_average_quadrature(double x, double width, int tracks);
double patch_box_average_quadrature(double y, double width, int tracks);

// The sine integral Si(t) = ∫₀ᵗ sin(s)/s ds: its power series up to |t| = 4, beyond it
// π/2 + Im E₁(it) with E₁ from its continued fraction (30 terms: ~1e-14 at t = 4).
double sine_integral(double t);

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
