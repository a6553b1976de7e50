#include "fit/brdf_grid.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <tuple>

#include "core/error.hpp"
#include "core/text.hpp"

namespace fxview::fit {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

std::vector<double> steps(double first, double last, int count) {
    std::vector<double> v(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) v[static_cast<size_t>(i)] = first + (last - first) * i / (count - 1);
    return v;
}

}  // namespace

glm::dvec3 BrdfGrid::light(size_t i) const {
    const double t = radians(theta_in[i]);
    return {-std::sin(t), 0.0, std::cos(t)};
}

glm::dvec3 BrdfGrid::camera(size_t o, size_t p) const {
    const double t = radians(theta_out[o]), f = radians(phi_out[p]);
    return {std::sin(t) * std::cos(f), std::sin(t) * std::sin(f), std::cos(t)};
}

BrdfGrid thesis_grid() { return uniform_grid(19, 37, 36); }

BrdfGrid uniform_grid(int theta_in_count, int theta_out_count, int phi_out_count) {
    if (theta_in_count < 2 || theta_out_count < 2 || phi_out_count < 2) throw UsageError("a BRDF grid needs at least 2 samples per angle");
    // The per-angle bound is 0.025° steps in φ, finer than any goniometer; the total bound keeps a grid's
    // memory (24 bytes a direction) and its CSV (about 80 bytes a line at 17 digits) within ~320 MB.
    if (theta_in_count > kMaxGridSamplesPerAngle || theta_out_count > kMaxGridSamplesPerAngle || phi_out_count > kMaxGridSamplesPerAngle)
        throw UsageError("a BRDF grid takes at most " + std::to_string(kMaxGridSamplesPerAngle) + " samples per angle");
    const double directions = double(theta_in_count) * theta_out_count * phi_out_count;
    if (directions > kMaxGridDirections)
        throw UsageError("a BRDF grid of " + std::to_string(theta_in_count) + " x " + std::to_string(theta_out_count) + " x " +
                         std::to_string(phi_out_count) + " directions is larger than the bound of " + std::to_string(kMaxGridDirections) +
                         " (a MERL table holds 1.46 million: use --merl-out for that density)");
    BrdfGrid grid;
    grid.theta_in = steps(0, 90, theta_in_count);
    grid.theta_out = steps(0, 90, theta_out_count);
    grid.phi_out = steps(0, 180, phi_out_count);
    grid.values.assign(grid.size(), {0, 0, 0});
    return grid;
}

bool is_uniform_full_grid(const BrdfGrid& grid) {
    const auto uniform = [](const std::vector<double>& v, double last) {
        if (v.size() < 2 || v.front() != 0.0 || std::abs(v.back() - last) > 1e-9) return false;
        const double step = last / static_cast<double>(v.size() - 1);
        for (size_t i = 0; i < v.size(); ++i)
            if (std::abs(v[i] - step * static_cast<double>(i)) > 1e-6) return false;
        return true;
    };
    return uniform(grid.theta_in, 90.0) && uniform(grid.theta_out, 90.0) && uniform(grid.phi_out, 180.0);
}

BrdfGrid read_brdf_grid(const std::string& path, const ResourceLimits& limits) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw Error(path + ": is a folder, not a BRDF grid file");
    checked_file_size(path, limits);
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open");
    using Key = std::tuple<double, double, double>;
    std::map<Key, std::pair<std::array<double, 3>, int>> samples;
    std::set<double> ti, to, po;
    std::string line;
    int number = 0;
    bool header = false;
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            if (line.rfind("theta_in_deg,theta_out_deg,phi_out_deg,r,g,b", 0) != 0)
                throw Error(path + ":" + std::to_string(number) + ": expected the header theta_in_deg,theta_out_deg,phi_out_deg,r,g,b");
            header = true;
            continue;
        }
        std::array<double, 6> v{};
        std::stringstream fields(line);
        std::string field;
        int count = 0;
        while (std::getline(fields, field, ',')) {
            if (count == 6) throw Error(path + ":" + std::to_string(number) + ": more than 6 values");
            // The whole field must be one number (blanks around it allowed): "0.25garbage" is an error.
            const size_t first = field.find_first_not_of(" \t\r"), last = field.find_last_not_of(" \t\r");
            const char* begin = field.data() + (first == std::string::npos ? field.size() : first);
            const char* stop = field.data() + (last == std::string::npos ? field.size() : last + 1);
            double& value = v[static_cast<size_t>(count)];
            const auto [end, parse_error] = std::from_chars(begin, stop, value);
            if (begin == stop || parse_error != std::errc() || end != stop || !std::isfinite(value))
                throw Error(path + ":" + std::to_string(number) + ": '" + excerpt(field) + "' is not a finite number");
            ++count;
        }
        if (count != 6) throw Error(path + ":" + std::to_string(number) + ": expected 6 values, found " + std::to_string(count));
        if (v[0] < 0 || v[0] > 90 || v[1] < 0 || v[1] > 90 || v[2] < 0 || v[2] > 180)
            throw Error(path + ":" + std::to_string(number) + ": angles must lie in theta 0..90 and phi 0..180 degrees");
        const Key key{v[0], v[1], v[2]};
        if (samples.count(key)) throw Error(path + ":" + std::to_string(number) + ": repeats the sample of line " + std::to_string(samples[key].second));
        samples[key] = {{v[3], v[4], v[5]}, number};
        ti.insert(v[0]);
        to.insert(v[1]);
        po.insert(v[2]);
    }
    if (!header) throw Error(path + ": empty (no header line)");
    BrdfGrid grid;
    grid.theta_in.assign(ti.begin(), ti.end());
    grid.theta_out.assign(to.begin(), to.end());
    grid.phi_out.assign(po.begin(), po.end());
    if (samples.size() != grid.size() || grid.size() == 0)
        throw Error(path + ": " + std::to_string(samples.size()) + " samples do not form a complete grid (" +
                    std::to_string(grid.theta_in.size()) + " x " + std::to_string(grid.theta_out.size()) + " x " +
                    std::to_string(grid.phi_out.size()) + " angles would need " + std::to_string(grid.size()) + ")");
    grid.values.resize(grid.size());
    for (size_t i = 0; i < grid.theta_in.size(); ++i)
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p)
                grid.values[grid.index(i, o, p)] = samples.at({grid.theta_in[i], grid.theta_out[o], grid.phi_out[p]}).first;
    return grid;
}

void write_brdf_grid(const BrdfGrid& grid, const std::string& path, int significant_digits) {
    std::ofstream out(path);
    if (!out) throw Error(path + ": cannot write");
    out << "# fxview BRDF grid: light on -x at theta_in, camera at (theta_out, phi_out from +x), normal +z; RGB in 1/sr\n";
    out << "theta_in_deg,theta_out_deg,phi_out_deg,r,g,b\n";
    out.precision(significant_digits);
    for (size_t i = 0; i < grid.theta_in.size(); ++i)
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) {
                const auto& v = grid.values[grid.index(i, o, p)];
                out << grid.theta_in[i] << ',' << grid.theta_out[o] << ',' << grid.phi_out[p] << ',' << v[0] << ',' << v[1] << ',' << v[2] << '\n';
            }
    if (!out) throw Error(path + ": write failed");
}

BrdfGrid tabulate(const BrdfGrid& grid, const std::function<std::array<double, 3>(const glm::dvec3& l, const glm::dvec3& v)>& f) {
    BrdfGrid out = grid;
    out.values.resize(grid.size());
    for (size_t i = 0; i < grid.theta_in.size(); ++i)
        for (size_t o = 0; o < grid.theta_out.size(); ++o)
            for (size_t p = 0; p < grid.phi_out.size(); ++p) out.values[grid.index(i, o, p)] = f(grid.light(i), grid.camera(o, p));
    return out;
}

std::vector<double> solid_angle_weights(const BrdfGrid& grid, double limit_deg) {
    const auto edges = [](const std::vector<double>& samples, double low, double high, size_t k) {
        const double below = k == 0 ? low : 0.5 * (samples[k - 1] + samples[k]);
        const double above = k + 1 == samples.size() ? high : 0.5 * (samples[k] + samples[k + 1]);
        return std::pair{std::clamp(below, low, high), std::clamp(above, low, high)};
    };
    std::vector<double> weights(grid.theta_out.size() * grid.phi_out.size(), 0.0);
    for (size_t o = 0; o < grid.theta_out.size(); ++o) {
        if (grid.theta_out[o] > limit_deg) continue;
        const auto [t0, t1] = edges(grid.theta_out, 0.0, limit_deg, o);
        for (size_t p = 0; p < grid.phi_out.size(); ++p) {
            const auto [f0, f1] = edges(grid.phi_out, 0.0, 180.0, p);
            weights[o * grid.phi_out.size() + p] = (std::cos(radians(t0)) - std::cos(radians(t1))) * radians(f1 - f0);
        }
    }
    return weights;
}

}  // namespace fxview::fit
