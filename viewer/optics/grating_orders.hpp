// The diffraction orders of a reflection grating (a CD's or DVD's tracks) as an energy-true renderer
// takes them: each order m reflects like a mirror with its own efficiency η_m, turned by the grating
// equation. With v the direction towards the viewer and l towards the light, both in the grating's
// frame (x across the tracks, y along them, z the normal), the order leaving towards v arrives from
// l_m = (m λ/d − v_x, −v_y, √(1 − l_x² − l_y²)) (Stam 1999; the in-plane form is sin θ_m = sin θ_i +
// m λ/d). The map v -> l_m shifts the tangential components, so it keeps projected solid angle: the
// order's radiance is η_m times the radiance arriving from l_m (radiance is conserved per order).
//
// Efficiencies: the mirror (zero) order keeps the fraction `zero_order` of the reflected light,
// neutrally, and the rest is shared by the propagating orders m ≠ 0 in proportion to sinc²(m a), the
// scalar-theory weights of a grating whose pits fill the fraction a of each period. Evanescent orders
// carry nothing and their share goes to the others, so Σ η_m = reflectance at every wavelength and
// view: diffracted energy does not depend on the number of coherently lit tracks, which only sets each
// order's angular width λ / (N d). A model (docs/diffraction.md), not a solution of Maxwell's equations.
#pragma once
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace fxview::optics {

struct GratingOrderModel {
    double spacing_nm = 1600.0;   // track spacing d
    double zero_order = 0.35;     // fraction of the reflected light in the mirror order
    double pit_fraction = 0.35;   // a: the part of each period the pits fill
    double reflectance = 0.9;     // of the coating: the sum of all orders' efficiencies
};

// The propagating orders for a view direction (grating frame, z > 0) at one wavelength: those m
// whose l_m is a real direction above the surface, |m λ/d − v_x|² + v_y² < 1.
struct OrderRange {
    int first = 0, last = 0;
};
OrderRange propagating_orders(glm::dvec3 view, double wavelength_nm, double spacing_nm);

// l_m in the grating frame, or nothing where order m is evanescent.
std::optional<glm::dvec3> order_incidence(glm::dvec3 view, int order, double wavelength_nm, double spacing_nm);

// η_m for the orders of `range` (the model above), index m - range.first; they sum to the reflectance.
std::vector<double> order_efficiencies(const GratingOrderModel& model, OrderRange range);

// A sphere light seen under the angular radius α, measured by chords: a direction δ radians from the
// light's centre lies at the chord c = |l - centre| = 2 sin(δ/2), and the light's edge at
// e = 2 sin(α/2). In chords the solid angle is planar (dω = 2π c dc), and they need no inverse
// trigonometry, whose GPU approximations are off by 1e-4 rad (Mesa's asin), a visible shift of a
// sharp edge. `light_edge_chord` gives e from sin α = radius / distance without cancellation.
double light_edge_chord(double sin_alpha);
// The radiance the light, of unit irradiance at normal incidence (as the point light gives), sends
// along a direction at chord c from its centre, seen through an order whose image is softened over
// the width w (the order's coherence width λ/(N d) and the pixel's extent, both as chords): the
// profile is a linear ramp from e - w/2 to e + w/2 (from the centre where e < w/2), divided by its
// exact irradiance 2π ∫ p(c) cos δ c dc, cos δ = 1 - c²/2. Sharp (w -> 0): 1 / (π sin²α) inside the
// disc; a point light (e = 0): a cone of chord radius w/2 that holds the same irradiance.
double sphere_light_radiance(double chord, double edge_chord, double width);
// The same where the ramp is 1 (inside the light's image): 1 / (2π ∫ p(c) cos δ c dc).
double sphere_light_ramp_scale(double edge_chord, double width);

}  // namespace fxview::optics
