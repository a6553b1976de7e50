// `compare --ground-truth` for the films: the exact film (characteristic matrices at every nm)
// mirroring the environment's model, over a rough film's lobe and a sized light, averaged over a
// spread of thicknesses: independent of the techniques' formulas and tables.
#pragma once
#include <functional>

#include "reference/reference.hpp"
#include "reference/thin_film_pixel.hpp"

namespace fxview::reference::thin_film {

// The physical film a technique stands for at one wavelength (a single film, a free film, a stack).
using StackAt = std::function<optics::Stack(const Film&, int nm)>;
// The surface a pixel's film lies on (BumpFresnelExact: tilted).
using SurfaceAt = std::function<ShadingInput(const ShadingInput&, const ReferenceContext&)>;

// `r` with its ground truth. `spread_thickness`: the technique reads ThicknessSpread (the Fourier
// films), and the truth averages the film over it.
Reference with_sky_truth(Reference r, StackAt stack_at_nm, bool spread_thickness = false, FilmAt film_at = film,
                         SurfaceAt surface = [](const ShadingInput& in, const ReferenceContext&) { return in; });

optics::Stack single_film_stack(const Film& f, int nm);
optics::Stack free_film_stack(const Film& f, int nm);

}  // namespace fxview::reference::thin_film
