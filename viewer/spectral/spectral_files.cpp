#include "spectral/spectral_files.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/text.hpp"

namespace fxview::spectral {
namespace {

bool to_double(std::string text, double& value) {
    if (!text.empty() && text.front() == '"' && text.back() == '"' && text.size() >= 2) text = text.substr(1, text.size() - 2);
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    // Spectral values beyond 1e30 are no measurement; their products would overflow.
    return !text.empty() && error == std::errc() && end == text.data() + text.size() && std::isfinite(value) && std::abs(value) <= 1e30;
}

std::string unquote(std::string text) {
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') return text.substr(1, text.size() - 2);
    return text;
}

}  // namespace

constexpr size_t kMaxDataSets = 4096;
constexpr size_t kMaxName = 256;

std::vector<NamedSpectrum> read_cgats(const std::string& path, Extrapolation outside, const ResourceLimits& limits) {
    checked_file_size(path, limits);
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open spectral file");
    std::string line, display = std::filesystem::path(path).stem().string();
    double start_nm = 0, end_nm = 0, bands = 0;  // from the header, when given
    std::vector<std::string> fields;
    std::vector<std::vector<std::string>> rows;
    std::vector<int> row_lines;
    int number = 0, format_line = 1;
    enum { Header, Format, Data, Done } state = Header;
    while (std::getline(file, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const auto w = words(line);
        if (w.empty() || w[0][0] == '#') continue;
        if (state == Header) {
            if (w[0] == "DISPLAY" && w.size() >= 2) display = unquote(line.substr(line.find(w[1])));
            else if (w[0] == "SPECTRAL_START_NM" || w[0] == "SPECTRAL_END_NM" || w[0] == "SPECTRAL_BANDS") {
                // Header numbers are checked where they stand: a wavelength in 0..100000 nm, a band
                // count in 2..100000 (colord-data's files have 81 to 471).
                double value = 0;
                const bool bands_field = w[0] == "SPECTRAL_BANDS";
                if (w.size() < 2 || !to_double(w[1], value) || value < (bands_field ? 2 : 0) || value > 100000 ||
                    (bands_field && value != std::floor(value)))
                    throw Error(path + ":" + std::to_string(number) + ": " + w[0] + " needs " +
                                (bands_field ? "a whole number in 2..100000" : "a wavelength in 0..100000 nm"));
                (w[0] == "SPECTRAL_START_NM" ? start_nm : w[0] == "SPECTRAL_END_NM" ? end_nm : bands) = value;
            }
            else if (w[0] == "BEGIN_DATA_FORMAT") {
                state = Format;
                format_line = number;
            }
            else if (w[0] == "BEGIN_DATA") state = Data;
        } else if (state == Format) {
            if (w[0] == "END_DATA_FORMAT") state = Header;
            else fields.insert(fields.end(), w.begin(), w.end());
        } else if (state == Data) {
            if (w[0] == "END_DATA") state = Done;
            else {
                // colord's files hold 1 to 14 data sets; each becomes a 4.8 KB spectrum.
                if (rows.size() == kMaxDataSets)
                    throw Error(path + ":" + std::to_string(number) + ": more than " + std::to_string(kMaxDataSets) + " data sets in one file");
                rows.push_back(w);
                row_lines.push_back(number);
            }
        }
    }
    if (fields.empty()) throw Error(path + ":1: not a CGATS spectral file (no BEGIN_DATA_FORMAT)");
    if (state != Done) throw Error(path + ":" + std::to_string(number) + ": CGATS data never ends (missing END_DATA)");
    std::vector<std::pair<int, double>> band_nm;  // field index -> wavelength
    int id_field = -1;
    for (size_t i = 0; i < fields.size(); ++i) {
        double nm = 0;
        if (fields[i].rfind("SPEC_", 0) == 0 && to_double(fields[i].substr(5), nm)) band_nm.emplace_back(static_cast<int>(i), nm);
        else if (fields[i] == "SAMPLE_ID" || fields[i] == "SAMPLE_NAME") id_field = static_cast<int>(i);
    }
    if (band_nm.empty()) throw Error(path + ":" + std::to_string(format_line) + ": CGATS file has no SPEC_nnn fields");
    // The header's start, end and band count are authoritative (some files name the fields in
    // other units, e.g. SPEC_300000 for 300 nm); field names are the fallback.
    if (bands >= 2 && end_nm > start_nm) {
        if (static_cast<size_t>(bands) != band_nm.size())
            throw Error(path + ":" + std::to_string(format_line) + ": SPECTRAL_BANDS says " + std::to_string(static_cast<int>(bands)) + " but " +
                        std::to_string(band_nm.size()) + " SPEC fields are declared");
        for (size_t i = 0; i < band_nm.size(); ++i) band_nm[i].second = start_nm + (end_nm - start_nm) * static_cast<double>(i) / (bands - 1);
    }
    std::vector<NamedSpectrum> spectra;
    for (size_t r = 0; r < rows.size(); ++r) {
        const auto& row = rows[r];
        const std::string where = path + ":" + std::to_string(row_lines[r]) + ": ";
        if (row.size() != fields.size())
            throw Error(where + "data set has " + std::to_string(row.size()) + " values, the format declares " +
                        std::to_string(fields.size()));
        std::vector<std::pair<double, double>> points;
        for (const auto& [index, nm] : band_nm) {
            double v = 0;
            if (!to_double(row[static_cast<size_t>(index)], v))
                throw Error(where + "'" + excerpt(row[static_cast<size_t>(index)]) + "' is not a finite number");
            points.emplace_back(nm, v);
        }
        NamedSpectrum named;
        named.name = id_field >= 0 ? unquote(row[static_cast<size_t>(id_field)])
                     : rows.size() == 1 ? display
                                        : display + "-" + std::to_string(r);
        if (named.name.size() > kMaxName) throw Error(where + "a spectrum name of " + std::to_string(named.name.size()) + " characters (at most 256)");
        try {
            named.spectrum = Spectrum::from_points(points, outside);
        } catch (const Error& error) {
            throw Error(where + error.what());
        }
        named.source = path;
        // Regular whole-nanometre sampling is remembered (CIE 15 sums line spectra at it).
        const int step = points.size() >= 2 ? static_cast<int>(std::lround(points[1].first - points[0].first)) : 0;
        bool regular = step > 0;
        for (size_t i = 0; regular && i < points.size(); ++i)
            regular = points[i].first == points[0].first + static_cast<double>(step) * static_cast<double>(i) &&
                      points[i].first == std::floor(points[i].first);
        if (regular) {
            named.data_start_nm = static_cast<int>(points.front().first);
            named.data_end_nm = static_cast<int>(points.back().first);
            named.data_step_nm = step;
        }
        spectra.push_back(std::move(named));
    }
    if (spectra.empty()) throw Error(path + ":" + std::to_string(number) + ": CGATS file holds no data set");
    return spectra;
}

void write_cgats(const std::string& path, const std::vector<NamedSpectrum>& spectra, int start_nm, int end_nm, int step_nm) {
    std::ofstream file(path);
    if (!file) throw Error(path + ": cannot write");
    const int bands = (end_nm - start_nm) / step_nm + 1;
    file << "SPECT\nORIGINATOR\t\"fxview\"\nDESCRIPTOR\t\"Spectral data\"\nSPECTRAL_START_NM\t" << start_nm
         << "\nSPECTRAL_END_NM\t" << end_nm << "\nSPECTRAL_BANDS\t" << bands << "\nNUMBER_OF_FIELDS\t" << bands + 1
         << "\nNUMBER_OF_SETS\t" << spectra.size() << "\nBEGIN_DATA_FORMAT\nSAMPLE_ID";
    for (int nm = start_nm; nm <= end_nm; nm += step_nm) file << "\tSPEC_" << nm;
    file << "\nEND_DATA_FORMAT\nBEGIN_DATA\n";
    file.precision(17);
    for (const auto& s : spectra) {
        file << '"' << s.name << '"';
        for (int nm = start_nm; nm <= end_nm; nm += step_nm) file << '\t' << s.spectrum.at(nm);
        file << '\n';
    }
    file << "END_DATA\n";
}

NamedSpectrum read_csv(const std::string& path, Extrapolation outside, const ResourceLimits& limits) {
    checked_file_size(path, limits);
    std::ifstream file(path);
    if (!file) throw Error(path + ": cannot open spectral file");
    std::vector<std::pair<double, double>> points;
    std::string line;
    int number = 0;
    bool header_allowed = true;
    while (std::getline(file, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#') continue;
        const size_t comma = line.find_first_of(",;\t");
        const auto trimmed = [](const std::string& text) {
            const auto w = words(text);
            return w.size() == 1 ? w[0] : std::string();
        };
        double nm = 0, v = 0;
        const bool ok = comma != std::string::npos && to_double(trimmed(line.substr(0, comma)), nm) &&
                        to_double(trimmed(line.substr(comma + 1)), v);
        if (!ok) {
            if (header_allowed) {  // one header line such as "nm,value"
                header_allowed = false;
                continue;
            }
            throw Error(path + ":" + std::to_string(number) + ": expected 'nm,value' (finite numbers), got '" + excerpt(line) + "'");
        }
        header_allowed = false;
        if (!points.empty() && nm <= points.back().first)
            throw Error(path + ":" + std::to_string(number) + ": wavelengths must increase (" + std::to_string(nm) + " nm)");
        points.emplace_back(nm, v);
    }
    if (points.size() < 2) throw Error(path + ":" + std::to_string(number) + ": a spectrum needs at least two 'nm,value' rows");
    return {std::filesystem::path(path).stem().string(), Spectrum::from_points(points, outside), path};
}

void write_csv(const std::string& path, const Spectrum& spectrum, int start_nm, int end_nm, int step_nm) {
    std::ofstream file(path);
    if (!file) throw Error(path + ": cannot write");
    file.precision(17);
    file << "nm,value\n";
    for (int nm = start_nm; nm <= end_nm; nm += step_nm) file << nm << ',' << spectrum.at(nm) << '\n';
}

}  // namespace fxview::spectral
