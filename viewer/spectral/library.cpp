#include "spectral/library.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/text.hpp"
#include "spectral/generators.hpp"
#include "spectral/spectral_files.hpp"

namespace fxview::spectral {

namespace fs = std::filesystem;

namespace {

std::vector<double> numbers(const std::string& text, size_t count, const std::string& source) {
    std::vector<double> values;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == ',') {
            double v = 0;
            const auto [end, error] = std::from_chars(text.data() + start, text.data() + i, v);
            if (error != std::errc() || end != text.data() + i) throw UsageError("spectrum source '" + source + "': bad number");
            values.push_back(v);
            start = i + 1;
        }
    if (values.size() != count)
        throw UsageError("spectrum source '" + source + "' needs " + std::to_string(count) + " number(s)");
    return values;
}

NamedSpectrum from_file(const std::string& path, const std::string& set, const std::string& label) {
    const std::string extension = lower_extension(path);
    if (extension == ".csv" || extension == ".txt") {
        NamedSpectrum named = read_csv(path, Extrapolation::Hold);
        named.source = label;
        return named;
    }
    const auto sets = read_cgats(path, Extrapolation::Hold);
    if (set.empty()) {
        if (sets.size() != 1) throw UsageError(path + " holds " + std::to_string(sets.size()) + " spectra: name one with #SET");
        NamedSpectrum named = sets[0];
        named.source = label;
        return named;
    }
    for (size_t i = 0; i < sets.size(); ++i)
        if (sets[i].name == set || std::to_string(i) == set) {
            NamedSpectrum named = sets[i];
            named.source = label;
            return named;
        }
    throw UsageError(path + " has no data set '" + set + "'");
}

}  // namespace

NamedSpectrum spectrum_from_source(const std::string& source, const std::string& base_dir, const std::string& colord_dir) {
    const size_t colon = source.find(':');
    const std::string scheme = colon == std::string::npos ? "" : source.substr(0, colon);
    const std::string rest = colon == std::string::npos ? source : source.substr(colon + 1);
    const size_t hash = rest.find('#');
    const std::string file = rest.substr(0, hash), set = hash == std::string::npos ? "" : rest.substr(hash + 1);
    if (scheme == "colord") return from_file(colord_dir + "/" + file, set, source);
    if (scheme == "file") return from_file((fs::path(base_dir) / file).string(), set, source);
    if (scheme == "constant") return {source, Spectrum::constant(numbers(rest, 1, source)[0]), source};
    if (scheme == "blackbody") return {source, blackbody(numbers(rest, 1, source)[0]), source};
    if (scheme == "daylight") return {source, cie_daylight(numbers(rest, 1, source)[0], colord_dir), source};
    if (scheme == "box") {
        const auto v = numbers(rest, 2, source);
        return {source, box(v[0], v[1]), source};
    }
    if (scheme == "gaussian") {
        const auto v = numbers(rest, 2, source);
        return {source, gaussian(v[0], v[1]), source};
    }
    if (scheme == "ramp") {
        const auto v = numbers(rest, 2, source);
        return {source, ramp(v[0], v[1]), source};
    }
    if (scheme.empty() && fs::is_regular_file(file)) return from_file(file, set, source);
    throw UsageError("unknown spectrum '" + source +
                     "' (a library name, a .csv/CGATS file, or colord:, file:, constant:, blackbody:, daylight:, box:, "
                     "gaussian:, ramp:)");
}

SpectralLibrary load_library(const std::string& path, const std::string& colord_dir) {
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open spectral library");
    SpectralLibrary library;
    library.path = path;
    std::string line;
    int number = 0;
    while (std::getline(file, line)) {
        ++number;
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        const std::string where = path + ":" + std::to_string(number) + ": ";
        const size_t equals = line.find('=');
        if (equals == std::string::npos) throw Error(where + "expected 'NAME = KIND SOURCE'");
        const auto trim = [](std::string text) {
            text.erase(0, text.find_first_not_of(" \t\r"));
            text.erase(text.find_last_not_of(" \t\r") + 1);
            return text;
        };
        const std::string name = trim(line.substr(0, equals)), rhs = trim(line.substr(equals + 1));
        const size_t space = rhs.find_first_of(" \t");
        const std::string kind = rhs.substr(0, space), source = space == std::string::npos ? "" : trim(rhs.substr(space));
        if (name.empty() || source.empty() || (kind != "emission" && kind != "lines" && kind != "reflectance"))
            throw Error(where + "expected 'NAME = emission|lines|reflectance SOURCE'");
        if (library.index_of(name) >= 0) throw Error(where + "spectrum '" + name + "' listed twice");
        LibraryEntry entry;
        try {
            entry.named = spectrum_from_source(source, fs::path(path).parent_path().string(), colord_dir);
        } catch (const std::exception& error) {
            throw Error(where + error.what());
        }
        entry.named.name = name;
        entry.kind = kind;
        if (kind == "emission" || kind == "lines") {
            // Normalised by the peak of the interpolated data, so that a line spectrum's comb carries
            // the same total power as the same data read as a smooth emission spectrum.
            double peak = 0;
            for (int nm = 360; nm <= 830; ++nm) peak = std::max(peak, entry.named.spectrum[nm]);
            if (peak <= 0) throw Error(where + "emission spectrum '" + name + "' is zero in 360-830 nm");
            if (kind == "lines") {
                try {
                    entry.named.spectrum = summation_comb(entry.named);
                } catch (const std::exception& error) {
                    throw Error(where + error.what());
                }
            }
            entry.named.spectrum = entry.named.spectrum.scaled(1.0 / peak);
        }
        library.entries.push_back(std::move(entry));
    }
    if (library.entries.empty()) throw Error(path + ": the spectral library lists no spectrum");
    return library;
}

int SpectralLibrary::index_of(const std::string& name) const {
    for (size_t i = 0; i < entries.size(); ++i)
        if (entries[i].named.name == name) return static_cast<int>(i);
    return -1;
}

const LibraryEntry& SpectralLibrary::at(const std::string& name_or_index) const {
    int index = index_of(name_or_index);
    if (index < 0) {
        int parsed = -1;
        const auto [end, error] = std::from_chars(name_or_index.data(), name_or_index.data() + name_or_index.size(), parsed);
        if (error == std::errc() && end == name_or_index.data() + name_or_index.size()) index = parsed;
    }
    if (index < 0 || index >= static_cast<int>(entries.size())) {
        std::string names;
        for (const auto& e : entries) names += (names.empty() ? "" : ", ") + e.named.name;
        throw UsageError("no spectrum '" + name_or_index + "' in " + path + " (it has " + names + ")");
    }
    return entries[static_cast<size_t>(index)];
}

std::vector<NamedSpectrum> SpectralLibrary::spectra() const {
    std::vector<NamedSpectrum> out;
    for (const auto& e : entries) out.push_back(e.named);
    return out;
}

}  // namespace fxview::spectral
