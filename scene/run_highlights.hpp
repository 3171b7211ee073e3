#pragma once
// The few lines a person reads after `coatfft run`: what the run found, from its summary.json
// object alone, in readable units to three significant digits. For a contact the contact radius
// (of the disk of equal area for a shape that is not round) and the peak pressure, each against
// Hertz's solution on the bare substrate and the bare top coating where the summary has it
// ("hertz_bare": a sphere or paraboloid under one load); for a [stress] scene the largest von
// Mises stress, where it is and in which medium, and the largest shear stress on each interface.
// The CLI prints them on stdout (cli/run_command.cpp); a known-load run without [stress] has none.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace coatfft::scene {

/// The lines, without line ends, e.g. "contact radius 13.6 µm (Hertz: 14.8 µm on the bare
/// substrate, 12.1 µm on the bare top coating)"; empty when the summary reports neither a
/// contact nor stresses. Keys the summary lacks or holds as null leave their line out.
std::vector<std::string> run_highlights(const nlohmann::json& summary);

}  // namespace coatfft::scene
