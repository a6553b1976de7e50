// The spectral library: named spectra with a fixed index (the index effects use to pick a spectrum
// from the packed texture). `spectra/library.txt` lists them, one per line:
//     NAME = KIND SOURCE
// KIND is `emission` (normalised to a peak of 1 in 360-830 nm, so that 8-bit storage keeps it) or
// `reflectance` (kept as is, 0..1). SOURCE is one of
//     colord:REL[#SET]   a CGATS file under /usr/share/colord (SET: name or 0-based index)
//     file:REL[#SET]     a CGATS or CSV file relative to the library file
//     constant:V  blackbody:KELVIN  daylight:KELVIN  box:FROM,TO  gaussian:CENTRE,SIGMA  ramp:FROM,TO
#pragma once
#include <string>
#include <vector>

#include "spectral/spectrum.hpp"

namespace fxview::spectral {

struct LibraryEntry {
    NamedSpectrum named;
    std::string kind;  // emission, lines (a fluorescent line spectrum, kept as its CIE 15 summation comb) or reflectance
};

struct SpectralLibrary {
    std::string path;
    std::vector<LibraryEntry> entries;

    int index_of(const std::string& name) const;  // -1 if absent
    const LibraryEntry& at(const std::string& name_or_index) const;  // UsageError naming the choices
    std::vector<NamedSpectrum> spectra() const;
};

SpectralLibrary load_library(const std::string& path, const std::string& colord_dir = "/usr/share/colord");

// A spectrum from a source expression (see above) or a file path (.csv, or CGATS .sp/.cmf/.it8).
NamedSpectrum spectrum_from_source(const std::string& source, const std::string& base_dir,
                                   const std::string& colord_dir = "/usr/share/colord");

}  // namespace fxview::spectral
