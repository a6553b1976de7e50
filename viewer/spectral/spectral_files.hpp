// Spectral data files. CGATS/IT8 (what Debian's colord-data ships: SPECTRAL_START_NM,
// SPECTRAL_END_NM, SPECTRAL_BANDS, one data set per row, SPEC_nnn fields, optional SAMPLE_ID) and
// CSV with `nm,value` rows (any spacing, '#' comments, an optional header line). Errors name the
// file and line.
#pragma once
#include <string>
#include <vector>

#include "core/limits.hpp"
#include "spectral/spectrum.hpp"

namespace fxview::spectral {

// Every data set of a CGATS file; names come from SAMPLE_ID, else DISPLAY (with an index if several).
std::vector<NamedSpectrum> read_cgats(const std::string& path, Extrapolation outside, const ResourceLimits& limits = {});
void write_cgats(const std::string& path, const std::vector<NamedSpectrum>& spectra, int start_nm, int end_nm, int step_nm);

NamedSpectrum read_csv(const std::string& path, Extrapolation outside, const ResourceLimits& limits = {});
void write_csv(const std::string& path, const Spectrum& spectrum, int start_nm, int end_nm, int step_nm);

}  // namespace fxview::spectral
