#pragma once
// FFTW wisdom: the plans FFTW measured, kept in a file so that a later run plans at once.
#include <string>

namespace coatfft {

/// Imports FFTW wisdom from the file at `path`; returns false when the file is missing or
/// unreadable (wisdom is an optimisation, so its absence is not an error).
bool load_fftw_wisdom(const std::string& path);

/// Exports the accumulated FFTW wisdom to the file at `path`; throws Error if it cannot be written.
void save_fftw_wisdom(const std::string& path);

}  // namespace coatfft
