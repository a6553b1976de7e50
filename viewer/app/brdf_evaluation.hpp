// A BRDF evaluated on the GPU over directions, through the BrdfGrid technique that every .brdf file
// gets (effects/lib/brdf_file.glsl): the grid that brdf-check sums, or one row across the plane of
// incidence for brdf-plot. Owns a headless GL context and the effect's session.
#pragma once
#include <memory>
#include <array>
#include <string>
#include <vector>

#include "app/brdf_check.hpp"
#include "app/effect_options.hpp"
#include "context/context.hpp"
#include "fit/merl.hpp"
#include "gl/render_target.hpp"
#include "image/image.hpp"
#include "render/effect_session.hpp"

namespace fxview::app {

// On an effect's session (the viewer's, or BrdfEvaluation's): whether it has the grid technique, and
// the grid or the plane of incidence rendered with its current parameter values. The session's
// technique and values are left as they were.
bool has_brdf_grid(const render::EffectSession& session);
// An effect whose BRDF() serves several models chooses one by a combo parameter BrdfModel listing
// them by technique name (effects/brdf/analytic.fx): set it to `technique` where it lists it.
void follow_technique(render::EffectSession& session, const std::string& technique);
// f(L, V) (or f(V, L)) at the directions of a sample set (app/brdf_check.hpp's layout, rows from
// the top), and brdf-check's renderers: the effect's on the GPU, a measured table's on the CPU (the
// table must outlive the renderer).
image::FloatImage evaluate_brdf_samples(render::EffectSession& session, const SampleRequest& request);
SampleRenderer gpu_sample_renderer(render::EffectSession& session);
// Whether the effect samples directions itself (a .brdf whose isFunc section defines sampleBRDF and
// pdfBRDF: the translator then declares FxFileSampler), so that brdf-check can use its sampler.
bool has_file_sampler(const render::EffectSession& session);
// A request's rows [first_row, first_row + rows) (GL's, from the bottom) drawn into `target` (of
// the request's size) with `values`, the rest of the target left as it is: the viewer spreads a
// check's renders over its frames this way. The session's technique and values stay as they were.
void draw_brdf_samples_rows(render::EffectSession& session, const effect::ParameterValues& values, const SampleRequest& request,
                            const gl::RenderTarget& target, int first_row, int rows);
SampleRenderer measured_sample_renderer(const fit::MerlBrdf& merl);
// f(L, V) at `samples` outgoing directions across the plane of incidence (azimuth φi), θo from -90°
// (mirror side) to 90°, sample k at θo = -90 + 180 (k + ½) / samples, for incidence θi in degrees.
image::FloatImage evaluate_brdf_plane(render::EffectSession& session, double incidence_degrees, int samples, bool swapped = false,
                                      double phi_i_degrees = 0.0);
// Rusinkiewicz's slice at difference azimuth φd: θh from 0 to 90° across, θd from 0 to 90° down the
// rows from the bottom (image rows from the top: θd decreasing), pixel centres; 0 below the surface.
image::FloatImage evaluate_brdf_slice(render::EffectSession& session, double phi_d_degrees, int width, int height);
// The hemisphere for incidence θi (azimuth φi): φo = 360° (a + ½) / width across, θo = 90° (b + ½) /
// height up from the bottom row.
image::FloatImage evaluate_brdf_hemisphere(render::EffectSession& session, double incidence_degrees, int width, int height,
                                           double phi_i_degrees = 0.0);

// The session's current technique on a sphere, `size` pixels square, 4x MSAA, in the default scene.
image::FloatImage render_lit_sphere(render::EffectSession& session, int size);

// A measured (MERL) BRDF at the directions of evaluate_brdf_plane, RGB, looked up on the CPU.
std::vector<std::array<double, 3>> measured_plane(const fit::MerlBrdf& merl, double incidence_degrees, int samples, double phi_i_degrees = 0.0);

class BrdfEvaluation {
public:
    // Throws UsageError when the effect has no BrdfGrid technique.
    BrdfEvaluation(const EffectOptions& effect, const std::string& backend);
    ~BrdfEvaluation();
    // The session to pass to the evaluate_brdf_* functions.
    render::EffectSession& session() { return *session_; }

private:
    std::unique_ptr<context::Context> context_;
    std::unique_ptr<render::EffectSession> session_;
};

}  // namespace fxview::app
