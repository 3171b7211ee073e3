#pragma once
// FFTW wisdom: the plans FFTW measured, kept in a file so that a later run plans at once.
#include <string>

namespace coatfft {

/// Imports FFTW wisdom from the file at `path`; returns false when the file is missing, is not a
/// regular file (a FIFO or a device is never opened) or does not hold wisdom (wisdom is an
/// optimisation, so its absence is not an error).
bool load_fftw_wisdom(const std::string& path);

/// Exports the accumulated FFTW wisdom to the file at `path`, atomically (a temporary file beside
/// it, then a rename); throws Error if it cannot be written, and refuses to replace anything but
/// a regular file.
void save_fftw_wisdom(const std::string& path);

/// Imports FFTW wisdom from its text; returns false when the text is not FFTW wisdom.
bool import_fftw_wisdom(const std::string& text);

/// The accumulated FFTW wisdom as text.
std::string export_fftw_wisdom();

/// Forgets the accumulated FFTW wisdom: later plans are planned anew at their own effort (FFTW
/// answers any plan, FFTW_ESTIMATE's too, from wisdom of the same problem at a higher effort).
void forget_fftw_wisdom();

}  // namespace coatfft
