// The analytic models the fitter offers (docs/fitting.md). Every one is linear in two scales per
// colour channel once its shape parameters θ (exponents, widths) are fixed:
//     f_c(l, v) = a_c · diffuse(l, v; θ) + b_c · specular(l, v; θ) + offset(l, v; θ)
// so that the best scales for a given θ are a small bounded least-squares problem solved exactly, and
// only θ (one or two numbers) has to be searched (fit/separable_solver.cpp). The offset carries what
// no scale multiplies, e.g. the grazing part (1 − h·v)⁵ of a Schlick Fresnel factor with F0 as b.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace fxview::fit {

// What a model needs of a direction pair, computed once per sample (normal +z, tangent +x): the
// cosines, the half vector's azimuth (anisotropic models) and ln(n·h).
struct SampleGeometry {
    double nl = 0, nv = 0, nh = 0, hv = 0;
    double cos2_phi_h = 1;  // cos² of the half vector's azimuth from the tangent; 1 where h = n
    double log_nh = 0;      // ln max(n·h, 1e-4) (ch. 4.2.4: the lobe's logarithm must exist)
};
SampleGeometry sample_geometry(const glm::dvec3& l, const glm::dvec3& v);

struct Basis {
    double diffuse = 0, specular = 0, offset = 0;
};

// A shape parameter, searched and polished on a log scale within [low, high].
struct ShapeParameter {
    std::string name;  // as the user sees it: "ns", "alpha"
    double low, high;
};

// One of the model's parameters as its technique reads them.
struct ModelParameter {
    std::string name;     // "kd", "F0", "alpha"
    std::string uniform;  // its uniform in effects/brdf/analytic.fx
    bool colour = false;  // vec3, else float
};

class FitModel {
public:
    virtual ~FitModel() = default;
    virtual std::string name() const = 0;   // the --model name
    virtual std::string title() const = 0;  // what the user reads
    virtual std::string technique() const = 0;  // in effects/brdf/analytic.fx
    virtual std::vector<ShapeParameter> shape() const = 0;
    virtual std::array<std::string, 2> scale_names() const = 0;  // a and b as the model calls them
    // The upper bound of b (1 where it is a reflectance such as F0 or Rs; a is >= 0 only).
    virtual double specular_upper() const { return 1.0; }
    virtual bool anisotropic() const { return false; }
    // The basis at shape θ; with `d_log_shape` (one Basis per shape parameter) also its derivatives
    // with respect to ln θ_k (analytic: the polish needs them accurate for sharp lobes).
    virtual Basis basis(const SampleGeometry& g, const double* shape, Basis* d_log_shape = nullptr) const = 0;
    virtual std::vector<ModelParameter> parameters() const = 0;
    // The parameters' values (in parameters()' order) from the fitted scales and shape.
    virtual std::vector<std::vector<double>> values(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                                    const std::vector<double>& shape) const = 0;
    // The model's value, per channel.
    std::array<double, 3> evaluate(const SampleGeometry& g, const std::array<double, 3>& a, const std::array<double, 3>& b,
                                   const std::vector<double>& shape) const {
        const Basis f = basis(g, shape.data());
        return {a[0] * f.diffuse + b[0] * f.specular + f.offset, a[1] * f.diffuse + b[1] * f.specular + f.offset,
                a[2] * f.diffuse + b[2] * f.specular + f.offset};
    }
};

// The default: the thesis' simplified Ashikhmin-Shirley (seed 000 eq. 4.28).
inline constexpr const char* kDefaultModel = "ashikhmin-fit";
// Every model, in the order `--model all` tries them. Throws UsageError for an unknown name.
const std::vector<std::string>& model_names();
std::shared_ptr<const FitModel> find_model(const std::string& name);

}  // namespace fxview::fit
