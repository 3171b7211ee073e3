// The coatfft command-line program. This is the only place where exceptions become exit codes:
// 2 for bad input (coatfft::InvalidArgument, bad flags), 3 for a contact solve that did not
// converge (outputs are written, summary.json says converged = false), 1 for a failed
// validate-frf check and anything else. A run stopped by Ctrl-C ends by SIGINT (status 130).
#include <CLI/CLI.hpp>
#include <iostream>
#include <string_view>

#include "cli/check_command.hpp"
#include "cli/frf_command.hpp"
#include "cli/run_command.hpp"
#include "cli/signal_cleanup.hpp"
#include "cli/surface_command.hpp"
#include "cli/validate_frf_command.hpp"
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "scene/resources.hpp"

namespace {

// CLI11 reads a lone unknown word as an extra argument and then asks for a subcommand; name it.
bool refuse_unknown_command(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return false;
  const std::string_view word = argv[1];
  if (word == "run" || word == "frf" || word == "check" || word == "validate-frf" ||
      word == "surface")
    return false;
  std::cerr << "coatfft: error: unknown command \"" << coatfft::detail::shorten(word)
            << "\" (commands: run, check, validate-frf, frf, surface; see coatfft --help)\n";
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"coatfft: surface displacements and contact of coated elastic half-spaces"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("coatfft ") + COATFFT_VERSION);

  coatfft::cli::RunOptions run;
  std::string max_memory;
  CLI::App* run_cmd = app.add_subcommand("run", "Compute the surface displacement of a scene");
  run_cmd->add_option("scene", run.scene, "Scene file (TOML)")->required();
  run_cmd->add_option("-o,--output", run.outdir, "Output folder")->required();
  run_cmd->add_option("--repeat", run.repeat, "Applications to time (median reported)")
      ->check(CLI::Range(1, coatfft::scene::max_repeat));
  run_cmd->add_option("--max-memory", max_memory,
                      "Memory the run may use, e.g. 4G (default: what the machine has available)");
  run_cmd->add_flag("--quiet", run.quiet,
                    "No progress on the terminal (warnings and errors are still printed)");

  coatfft::cli::CheckOptions check;
  std::string check_max_memory;
  CLI::App* check_cmd = app.add_subcommand(
      "check",
      "Validate a scene as run does and print what it would compute (JSON), computing "
      "and writing nothing");
  check_cmd->add_option("scene", check.scene, "Scene file (TOML)")->required();
  check_cmd->add_option("--max-memory", check_max_memory, "As for run");

  coatfft::cli::ValidateFrfOptions validate;
  CLI::App* validate_cmd = app.add_subcommand(
      "validate-frf",
      "Check a scene's [frf] table against its [substrate] and [[coating]] (exit 1 if a check "
      "fails)");
  validate_cmd->add_option("scene", validate.scene, "Scene file (TOML) with [frf] and [substrate]")
      ->required();
  validate_cmd->add_option("--tolerance", validate.tolerance,
                           "Largest relative difference accepted (default 1e-6)");

  coatfft::cli::FrfOptions frf;
  CLI::App* frf_cmd = app.add_subcommand("frf", "Print the FRF of a scene's body as a CSV table");
  frf_cmd
      ->add_option("scene", frf.scene,
                   "Scene file (TOML); only [substrate] and [[coating]] are used")
      ->required();
  frf_cmd->add_option("-o,--output", frf.output, "CSV file (default: standard output)");
  frf_cmd->add_option("--k-min", frf.k_min, "Smallest wavenumber [rad/m]");
  frf_cmd->add_option("--k-max", frf.k_max, "Largest wavenumber [rad/m]");
  frf_cmd->add_option("--points", frf.points, "Number of log-spaced wavenumbers")
      ->check(CLI::Range(2L, coatfft::scene::max_frf_points));

  coatfft::cli::SurfaceOptions surface;
  CLI::App* surface_cmd = app.add_subcommand(
      "surface", "Write a periodic self-affine random surface (heights [m]) as a .npy file");
  surface_cmd->add_option("-o,--output", surface.output, "Output .npy file")->required();
  surface_cmd->add_option("--nx", surface.nx, "Cells along x (even)")->required();
  surface_cmd->add_option("--ny", surface.ny, "Cells along y (even)")->required();
  surface_cmd->add_option("--lx", surface.lx, "Domain length along x [m]")->required();
  surface_cmd->add_option("--ly", surface.ly, "Domain length along y [m]")->required();
  surface_cmd->add_option("--hurst", surface.hurst, "Hurst exponent H in (0, 1]")->required();
  surface_cmd->add_option("--rms-height", surface.rms_height, "rms height [m]");
  surface_cmd->add_option("--rms-slope", surface.rms_slope, "rms slope [-]");
  surface_cmd->add_option("--short-cutoff", surface.short_cutoff,
                          "Shortest wavelength [m] (default 2 max(dx, dy))");
  surface_cmd->add_option("--long-cutoff", surface.long_cutoff,
                          "Roll-off wavelength [m] (default max(lx, ly): no roll-off)");
  surface_cmd->add_option("--seed", surface.seed,
                          "Seed of the random phases, an integer in [0, 2^64 - 1] (default 0)");

  if (refuse_unknown_command(argc, argv)) return 2;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // One line, like every other refusal.
    std::cerr << "coatfft: error: " << coatfft::detail::shorten(e.what(), 200)
              << " (see coatfft --help)\n";
    return 2;
  }

  try {
    if (!max_memory.empty())
      run.max_memory = coatfft::scene::parse_memory_size(max_memory, "--max-memory");
    if (*run_cmd && coatfft::cli::run_command(run) == coatfft::scene::RunStatus::not_converged) {
      std::cerr << "coatfft: warning: the contact solver did not converge (see summary.json)\n";
      return 3;
    }
    if (*frf_cmd) coatfft::cli::frf_command(frf);
    if (*surface_cmd) coatfft::cli::surface_command(surface);
    if (*check_cmd) {
      if (!check_max_memory.empty())
        check.max_memory = coatfft::scene::parse_memory_size(check_max_memory, "--max-memory");
      coatfft::cli::check_command(check);
    }
    if (*validate_cmd && !coatfft::cli::validate_frf_command(validate)) return 1;
  } catch (const coatfft::Interrupted&) {
    // Ctrl-C during `run`: the computation has stopped and unwound, its staged output removed.
    std::cerr << "coatfft: interrupted\n" << std::flush;
    coatfft::cli::end_by_sigint();
  } catch (const coatfft::InvalidArgument& e) {
    std::cerr << "coatfft: error: " << e.what() << '\n';
    return 2;
  } catch (const std::bad_alloc&) {
    std::cerr << "coatfft: error: out of memory (the estimate of docs/scene_format.md, \"Limits\", "
                 "was too low for this machine): use fewer cells or --max-memory\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "coatfft: internal error: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
