// The models of fit_model.hpp. Each basis is checked against the renderer's CPU model
// (viewer/brdf/models.cpp) and its derivatives against finite differences (tests/test_fit_models.cpp).
#include <cmath>
#include <limits>
#include <numbers>

#include "brdf/microfacet.hpp"
#include "brdf/models.hpp"
#include "core/error.hpp"
#include "fit/fit_model.hpp"

namespace fxview::fit {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::vector<double> rgb(const std::array<double, 3>& x) { return {x[0], x[1], x[2]}; }

double pow5(double x) { return x * x * x * x * x; }

// (n + 1)/(8π) (n·h)^n / ((h·v) max(n·l, n·v)): the thesis' lobe (eq. 4.28) and the isotropic
// Ashikhmin-Shirley specular term without Fresnel; its derivative with respect to ln n.
double ashikhmin_lobe(const SampleGeometry& g, double n, double* d_log_n) {
    const double lobe = (n + 1.0) / (8.0 * kPi) * std::exp(n * g.log_nh) / (g.hv * std::max(g.nl, g.nv));
    if (d_log_n) *d_log_n = n * lobe * (1.0 / (n + 1.0) + g.log_nh);
    return lobe;
}

// Splits a Schlick-Fresnel-weighted lobe L · (F0 + (1 − F0)(1 − h·v)⁵) into F0's part and the rest.
Basis fresnel_weighted(double diffuse, double lobe, double hv) {
    const double grazing = pow5(1.0 - std::max(hv, 0.0));
    return {diffuse, lobe * (1.0 - grazing), lobe * grazing};
}

class AshikhminShirleyFitModel final : public FitModel {
public:
    std::string name() const override { return "ashikhmin-fit"; }
    std::string title() const override { return "Ashikhmin-Shirley, simplified, without Fresnel"; }
    std::string technique() const override { return "AshikhminShirleyFit"; }
    std::vector<ShapeParameter> shape() const override { return {{"ns", 1e-2, 1e6}}; }
    std::array<std::string, 2> scale_names() const override { return {"cd", "cs"}; }
    Basis basis(const SampleGeometry& g, const double* shape, Basis* d) const override {
        double d_lobe = 0;
        const double lobe = ashikhmin_lobe(g, shape[0], d ? &d_lobe : nullptr);
        if (d) d[0] = {0.0, d_lobe, 0.0};
        return {1.0 / kPi, lobe, 0.0};
    }
    std::vector<ModelParameter> parameters() const override {
        return {{"cd", "FitDiffuse", true}, {"cs", "FitSpecular", true}, {"ns", "FitExponent", false}};
    }
    std::vector<std::vector<double>> values(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                            const std::vector<double>& shape) const override {
        return {rgb(a), rgb(b), {shape[0]}};
    }
};

// Ashikhmin-Shirley with its Fresnel term and Fresnel-weighted diffuse part (seed 000 eq. 4.11-4.14),
// Rd and Rs per channel. Per channel f = a D + b L (1 − (1 − h·v)⁵) + L (1 − h·v)⁵ with a = Rd (1 − Rs),
// b = Rs: linear in (a, b). Isotropic (nu = nv = n), or anisotropic with nu along the tangent.
class AshikhminShirleyModel final : public FitModel {
public:
    explicit AshikhminShirleyModel(bool anisotropic) : anisotropic_(anisotropic) {}
    std::string name() const override { return anisotropic_ ? "ashikhmin-aniso" : "ashikhmin-fresnel"; }
    std::string title() const override {
        return anisotropic_ ? "Ashikhmin-Shirley, anisotropic (nu along the light's plane), with Fresnel"
                            : "Ashikhmin-Shirley with Fresnel (Rs), isotropic";
    }
    std::string technique() const override { return "AshikhminShirley"; }
    std::vector<ShapeParameter> shape() const override {
        if (anisotropic_) return {{"nu", 1e-2, 1e6}, {"nv", 1e-2, 1e6}};
        return {{"n", 1e-2, 1e6}};
    }
    std::array<std::string, 2> scale_names() const override { return {"Rd (1 - Rs)", "Rs"}; }
    bool anisotropic() const override { return anisotropic_; }
    Basis basis(const SampleGeometry& g, const double* shape, Basis* d) const override {
        const auto grazing = [](double x) { return 1.0 - pow5(1.0 - x / 2.0); };
        const double diffuse = 28.0 / (23.0 * kPi) * grazing(g.nl) * grazing(g.nv);
        double lobe = 0;
        double d_lobe[2] = {0, 0};
        if (!anisotropic_) {
            lobe = ashikhmin_lobe(g, shape[0], d ? &d_lobe[0] : nullptr);
        } else {
            const double nu = shape[0], nv = shape[1], cos2 = g.cos2_phi_h, sin2 = 1.0 - cos2;
            lobe = std::sqrt((nu + 1.0) * (nv + 1.0)) / (8.0 * kPi) * std::exp((nu * cos2 + nv * sin2) * g.log_nh) /
                   (g.hv * std::max(g.nl, g.nv));
            d_lobe[0] = nu * lobe * (0.5 / (nu + 1.0) + cos2 * g.log_nh);
            d_lobe[1] = nv * lobe * (0.5 / (nv + 1.0) + sin2 * g.log_nh);
        }
        if (d)
            for (size_t k = 0; k < (anisotropic_ ? 2u : 1u); ++k) d[k] = fresnel_weighted(0.0, d_lobe[k], g.hv);
        return fresnel_weighted(diffuse, lobe, g.hv);
    }
    std::vector<ModelParameter> parameters() const override {
        return {{"Rd", "ASDiffuse", true}, {"Rs", "ASSpecular", true}, {"nu", "Nu", false}, {"nv", "Nv", false}};
    }
    std::vector<std::vector<double>> values(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                            const std::vector<double>& shape) const override {
        std::array<double, 3> rd{};
        for (size_t c = 0; c < 3; ++c) rd[c] = b[c] < 1.0 ? a[c] / (1.0 - b[c]) : 0.0;
        return {rgb(rd), rgb(b), {shape[0]}, {anisotropic_ ? shape[1] : shape[0]}};
    }

private:
    bool anisotropic_;
};

// Cook-Torrance microfacet models with Fresnel-Schlick F0 per channel: kd/π + D G F / (4 (n·l)(n·v)).
class MicrofacetModel final : public FitModel {
public:
    enum class Distribution { GGX, Beckmann };
    explicit MicrofacetModel(Distribution d) : distribution_(d) {}
    std::string name() const override { return distribution_ == Distribution::GGX ? "ggx" : "beckmann"; }
    std::string title() const override {
        return distribution_ == Distribution::GGX ? "Cook-Torrance: GGX, height-correlated Smith, Schlick F0"
                                                  : "Cook-Torrance: Beckmann, V-cavity, Schlick F0";
    }
    std::string technique() const override { return distribution_ == Distribution::GGX ? "CookTorranceGGX" : "CookTorranceBeckmannSchlick"; }
    std::vector<ShapeParameter> shape() const override {
        return {{distribution_ == Distribution::GGX ? "alpha" : "m", 1e-3, 1.0}};
    }
    std::array<std::string, 2> scale_names() const override { return {"kd", "F0"}; }
    Basis basis(const SampleGeometry& g, const double* shape, Basis* d) const override {
        const double width = shape[0];
        const double cos2 = g.nh * g.nh, tan2 = (1.0 - cos2) / std::max(cos2, 1e-300);
        double dg = 0, d_dg = 0;  // D G and its derivative with respect to ln(width)
        if (distribution_ == Distribution::GGX) {
            const double a2 = width * width, q = cos2 * (a2 - 1.0) + 1.0;
            const double D = brdf::ggx_distribution(g.nh, width);
            const auto tau = [](double x) { return (1.0 - x * x) / (x * x); };
            const double root_l = std::sqrt(1.0 + a2 * tau(g.nl)), root_v = std::sqrt(1.0 + a2 * tau(g.nv));
            const double G = 1.0 / (1.0 + 0.5 * (root_l - 1.0) + 0.5 * (root_v - 1.0));
            // α dΛ/dα = α² τ / (2 √(1 + α² τ)); dG/d ln α = −G² Σ α dΛ/dα; dD/d ln α = D (2 − 4 α² (n·h)² / q).
            const double d_lambda = a2 * tau(g.nl) / (2.0 * root_l) + a2 * tau(g.nv) / (2.0 * root_v);
            dg = D * G;
            d_dg = D * (2.0 - 4.0 * a2 * cos2 / q) * G - D * G * G * d_lambda;
        } else {
            const double D = g.nh > 0 ? brdf::beckmann_distribution(g.nh, width) : 0.0;
            const double G = brdf::v_cavity_geometry(g.nh, g.nv, g.nl, g.hv);
            dg = D * G;
            d_dg = dg * (2.0 * tan2 / (width * width) - 2.0);  // dD/d ln m = D (2 tan²/m² − 2)
        }
        const double scale = 1.0 / (4.0 * g.nl * g.nv);
        if (d) d[0] = fresnel_weighted(0.0, d_dg * scale, g.hv);
        return fresnel_weighted(1.0 / kPi, dg * scale, g.hv);
    }
    std::vector<ModelParameter> parameters() const override {
        if (distribution_ == Distribution::GGX) return {{"kd", "GGXDiffuse", true}, {"F0", "GGXF0", true}, {"alpha", "GGXAlpha", false}};
        return {{"kd", "CTSDiffuse", true}, {"F0", "CTSF0", true}, {"m", "CTSSlope", false}};
    }
    std::vector<std::vector<double>> values(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                            const std::vector<double>& shape) const override {
        return {rgb(a), rgb(b), {shape[0]}};
    }

private:
    Distribution distribution_;
};

// Normalised Blinn-Phong and Ward's isotropic model: kd/π + ks lobe, ks unbounded above (neither
// lobe is a reflectance at normal incidence).
class LobeModel final : public FitModel {
public:
    enum class Lobe { BlinnPhong, Ward };
    explicit LobeModel(Lobe lobe) : lobe_(lobe) {}
    std::string name() const override { return lobe_ == Lobe::BlinnPhong ? "blinn-phong" : "ward"; }
    std::string title() const override { return lobe_ == Lobe::BlinnPhong ? "Blinn-Phong, normalised" : "Ward, isotropic"; }
    std::string technique() const override { return lobe_ == Lobe::BlinnPhong ? "BlinnPhong" : "Ward"; }
    std::vector<ShapeParameter> shape() const override {
        if (lobe_ == Lobe::BlinnPhong) return {{"n", 1e-2, 1e6}};
        return {{"alpha", 1e-3, 1.0}};
    }
    std::array<std::string, 2> scale_names() const override { return {"kd", "ks"}; }
    double specular_upper() const override { return kInfinity; }
    Basis basis(const SampleGeometry& g, const double* shape, Basis* d) const override {
        double lobe = 0, d_lobe = 0;
        if (lobe_ == Lobe::BlinnPhong) {
            const double n = shape[0];
            lobe = (n + 8.0) / (8.0 * kPi) * std::exp(n * g.log_nh);
            d_lobe = n * lobe * (1.0 / (n + 8.0) + g.log_nh);
        } else {
            const double a2 = shape[0] * shape[0], cos2 = g.nh * g.nh;
            const double tan2 = (1.0 - cos2) / std::max(cos2, 1e-300);
            lobe = g.nh > 0 ? std::exp(-tan2 / a2) / (4.0 * kPi * a2 * std::sqrt(g.nl * g.nv)) : 0.0;
            d_lobe = lobe * (2.0 * tan2 / a2 - 2.0);
        }
        if (d) d[0] = {0.0, d_lobe, 0.0};
        return {1.0 / kPi, lobe, 0.0};
    }
    std::vector<ModelParameter> parameters() const override {
        if (lobe_ == Lobe::BlinnPhong) return {{"kd", "BlinnDiffuse", true}, {"ks", "BlinnSpecular", true}, {"n", "BlinnExponent", false}};
        return {{"kd", "WardDiffuse", true}, {"ks", "WardSpecular", true}, {"alpha", "WardAlpha", false}};
    }
    std::vector<std::vector<double>> values(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                            const std::vector<double>& shape) const override {
        return {rgb(a), rgb(b), {shape[0]}};
    }

private:
    Lobe lobe_;
};

}  // namespace

SampleGeometry sample_geometry(const glm::dvec3& l, const glm::dvec3& v) {
    const glm::dvec3 h = glm::normalize(l + v);
    SampleGeometry g;
    g.nl = l.z;
    g.nv = v.z;
    g.nh = h.z;
    g.hv = glm::dot(h, v);
    const double tangential = h.x * h.x + h.y * h.y;
    g.cos2_phi_h = tangential > 0 ? h.x * h.x / tangential : 1.0;
    g.log_nh = std::log(std::max(h.z, 1e-4));
    return g;
}

const std::vector<std::string>& model_names() {
    static const std::vector<std::string> names = {"ashikhmin-fit", "ashikhmin-fresnel", "ashikhmin-aniso", "ggx",
                                                   "beckmann",      "blinn-phong",       "ward"};
    return names;
}

std::shared_ptr<const FitModel> find_model(const std::string& name) {
    if (name == "ashikhmin-fit") return std::make_shared<AshikhminShirleyFitModel>();
    if (name == "ashikhmin-fresnel") return std::make_shared<AshikhminShirleyModel>(false);
    if (name == "ashikhmin-aniso") return std::make_shared<AshikhminShirleyModel>(true);
    if (name == "ggx") return std::make_shared<MicrofacetModel>(MicrofacetModel::Distribution::GGX);
    if (name == "beckmann") return std::make_shared<MicrofacetModel>(MicrofacetModel::Distribution::Beckmann);
    if (name == "blinn-phong") return std::make_shared<LobeModel>(LobeModel::Lobe::BlinnPhong);
    if (name == "ward") return std::make_shared<LobeModel>(LobeModel::Lobe::Ward);
    std::string known;
    for (const auto& n : model_names()) known += (known.empty() ? "" : ", ") + n;
    throw UsageError("unknown model '" + name + "' (" + known + ", or all)");
}

}  // namespace fxview::fit
