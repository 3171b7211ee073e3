// The coatfft command-line program. This is the only place where exceptions become exit codes:
// 2 for bad input (coatfft::InvalidArgument, bad flags), 3 for a contact solve that did not
// converge (outputs are written, summary.json says converged = false), 1 for a failed
// validate-frf check and anything else. A run stopped by Ctrl-C ends by SIGINT (status 130).
#include <CLI/CLI.hpp>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/check_command.hpp"
#include "cli/frf_command.hpp"
#include "cli/run_command.hpp"
#include "cli/signal_cleanup.hpp"
#include "cli/surface_command.hpp"
#include "cli/topography_command.hpp"
#include "cli/validate_frf_command.hpp"
#include "core/detail/mpi_launch.hpp"
#ifdef COATFFT_WITH_MPI
#include "distributed/detail/agreed_refusal.hpp"
#include "distributed/mpi_session.hpp"
#endif
#include "core/detail/shorten.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "scene/resources.hpp"

namespace {

// CLI11 reads a lone unknown word as an extra argument and then asks for a subcommand; name it.
std::string unknown_command(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return {};
  const std::string_view word = argv[1];
  if (word == "run" || word == "frf" || word == "check" || word == "validate-frf" ||
      word == "surface" || word == "topography")
    return {};
  return "unknown command \"" + coatfft::detail::shorten(word) +
         "\" (commands: run, check, validate-frf, frf, surface, topography; see coatfft --help)";
}

// A subcommand, and what running it returns: the exit status.
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

// `run` on this process, or on every rank of an MPI launch of several (docs/scale.md).
coatfft::scene::RunStatus run_here(const coatfft::cli::RunOptions& options) {
#ifdef COATFFT_WITH_MPI
  if (coatfft::detail::mpi_launch().size > 1)
    return coatfft::cli::run_command(options, coatfft::Communicator::world());
#endif
  return coatfft::cli::run_command(options);
}

// Each command's arguments live as long as its runner (shared with it), bound to its flags.
Command add_run(CLI::App& app) {
  struct Args {
    coatfft::cli::RunOptions options;
    std::string max_memory;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand("run", "Compute the surface displacement of a scene");
  cmd->add_option("scene", args->options.scene, "Scene file (TOML)")->required();
  cmd->add_option("-o,--output", args->options.outdir, "Output folder")->required();
  cmd->add_option("--repeat", args->options.repeat, "Applications to time (median reported)")
      ->check(CLI::Range(1, coatfft::scene::max_repeat));
  cmd->add_option("--max-memory", args->max_memory,
                  "Memory the run may use, e.g. 4G (default: what the machine has available)");
  cmd->add_flag(
      "--quiet", args->options.quiet,
      "No progress and no lines of results on the terminal (warnings and errors are still "
      "printed)");
  return {cmd, [args] {
            if (!args->max_memory.empty())
              args->options.max_memory =
                  coatfft::scene::parse_memory_size(args->max_memory, "--max-memory");
            if (run_here(args->options) != coatfft::scene::RunStatus::ok) {
              std::cerr << "coatfft: warning: the contact solver did not converge (see "
                           "summary.json)\n";
              return 3;
            }
            return 0;
          }};
}

Command add_check(CLI::App& app) {
  struct Args {
    coatfft::cli::CheckOptions options;
    std::string max_memory;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "check",
      "Validate a scene as run does and print what it would compute (JSON), computing "
      "and writing nothing");
  cmd->add_option("scene", args->options.scene, "Scene file (TOML)")->required();
  cmd->add_option("--max-memory", args->max_memory, "As for run");
  return {cmd, [args] {
            if (!args->max_memory.empty())
              args->options.max_memory =
                  coatfft::scene::parse_memory_size(args->max_memory, "--max-memory");
            coatfft::cli::check_command(args->options);
            return 0;
          }};
}

Command add_validate_frf(CLI::App& app) {
  auto options = std::make_shared<coatfft::cli::ValidateFrfOptions>();
  CLI::App* cmd = app.add_subcommand(
      "validate-frf",
      "Check a scene's [frf] table against its [substrate] and [[coating]] (exit 1 if a check "
      "fails)");
  cmd->add_option("scene", options->scene, "Scene file (TOML) with [frf] and [substrate]")
      ->required();
  cmd->add_option("--tolerance", options->tolerance,
                  "Largest relative difference accepted (default 1e-6)");
  return {cmd, [options] { return coatfft::cli::validate_frf_command(*options) ? 0 : 1; }};
}

Command add_frf(CLI::App& app) {
  auto options = std::make_shared<coatfft::cli::FrfOptions>();
  CLI::App* cmd = app.add_subcommand("frf", "Print the FRF of a scene's body as a CSV table");
  cmd->add_option("scene", options->scene,
                  "Scene file (TOML); only [substrate] and [[coating]] are used")
      ->required();
  cmd->add_option("-o,--output", options->output, "CSV file (default: standard output)");
  cmd->add_option("--k-min", options->k_min, "Smallest wavenumber [rad/m]");
  cmd->add_option("--k-max", options->k_max, "Largest wavenumber [rad/m]");
  cmd->add_option("--points", options->points, "Number of log-spaced wavenumbers")
      ->check(CLI::Range(2L, coatfft::scene::max_frf_points));
  return {cmd, [options] {
            coatfft::cli::frf_command(*options);
            return 0;
          }};
}

Command add_surface(CLI::App& app) {
  auto o = std::make_shared<coatfft::cli::SurfaceOptions>();
  CLI::App* cmd = app.add_subcommand(
      "surface", "Write a periodic self-affine random surface (heights [m]) as .npy or .nc");
  cmd->add_option("-o,--output", o->output, "Output file: .npy, or .nc (NetCDF)")->required();
  cmd->add_option("--nx", o->nx, "Cells along x (even)")->required();
  cmd->add_option("--ny", o->ny, "Cells along y (even)")->required();
  cmd->add_option("--lx", o->lx, "Domain length along x [m]")->required();
  cmd->add_option("--ly", o->ly, "Domain length along y [m]")->required();
  cmd->add_option("--hurst", o->hurst, "Hurst exponent H in (0, 1]")->required();
  cmd->add_option("--rms-height", o->rms_height, "rms height [m]");
  cmd->add_option("--rms-slope", o->rms_slope, "rms slope [-]");
  cmd->add_option("--short-cutoff", o->short_cutoff,
                  "Shortest wavelength [m] (default 2 max(dx, dy))");
  cmd->add_option("--long-cutoff", o->long_cutoff,
                  "Roll-off wavelength [m] (default max(lx, ly): no roll-off)");
  cmd->add_option("--seed", o->seed,
                  "Seed of the random phases, an integer in [0, 2^64 - 1] (default 0)");
  cmd->add_flag("--overwrite", o->overwrite, "Replace the output file if it exists");
  return {cmd, [o] {
#ifdef COATFFT_WITH_MPI
            if (coatfft::detail::mpi_launch().size > 1) {
              coatfft::cli::surface_command(*o, coatfft::Communicator::world());
              return 0;
            }
#endif
            coatfft::cli::surface_command(*o);
            return 0;
          }};
}

// --max-memory as typed: bytes, or none when not given.
std::optional<double> memory_limit(const std::string& text) {
  if (text.empty()) return std::nullopt;
  return coatfft::scene::parse_memory_size(text, "--max-memory");
}

Command add_topography(CLI::App& app) {
  struct Args {
    coatfft::cli::TopographyOptions options;
    std::string max_memory;
  };
  auto args = std::make_shared<Args>();
  coatfft::cli::TopographyOptions* o = &args->options;
  CLI::App* cmd = app.add_subcommand(
      "topography",
      "Read a measured topography, print its summary (JSON), write it as .npy or .nc");
  cmd->add_option("file", o->input, "Topography file: .npy, .csv/.txt/.asc/.xyz, .nc, .x3p or .sdf")
      ->required();
  cmd->add_option("-o,--output", o->output, "Write the heights [m] as .npy or .nc");
  cmd->add_option("--unit", o->unit, "Unit of a file that carries none: m, mm, um, nm, A");
  cmd->add_option("--detrend", o->detrend, "none (default), mean or plane");
  cmd->add_option("--missing", o->missing,
                  "Missing points: refuse (default) or fill (harmonic interpolation)");
  cmd->add_option("--lx", o->lx, "Size along x [m] of a file that carries none");
  cmd->add_option("--ly", o->ly, "Size along y [m] of a file that carries none");
  cmd->add_flag("--gap", o->gap,
                "Write the gap max(z) - z [m] a rigid flat sees (after --detrend) as .npy, for "
                "[contact] indenter = \"height_map\", instead of the heights");
  cmd->add_option("--max-memory", args->max_memory,
                  "Memory reading and filling the map may use, e.g. 4G (default: what the "
                  "machine has available)");
  cmd->add_flag("--overwrite", o->overwrite, "Replace the output file if it exists");
  return {cmd, [args] {
            args->options.max_memory = memory_limit(args->max_memory);
            coatfft::cli::topography_command(args->options);
            return 0;
          }};
}

// The name of the command the user chose.
std::string chosen_name(const std::vector<Command>& commands) {
  for (const Command& command : commands)
    if (*command.app) return command.app->get_name();
  return {};
}

// Runs the command the user chose; its exceptions become exit statuses.
int run_chosen(const std::vector<Command>& commands) {
  try {
    for (const Command& command : commands)
      if (*command.app) return command.run();
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

#ifdef COATFFT_WITH_MPI
// Several ranks: MPI started on each, then every rank's own refusal of its command line (a bad
// flag, another command than rank 0's: an MPMD launch gives each rank its own) agreed before the
// command's first collective step, and named by rank 0 on one line.
int run_on_ranks(const std::vector<Command>& commands, const std::string& refusal, int argc,
                 char** argv) {
  const coatfft::MpiSession mpi(argc, argv);
  const coatfft::Communicator world = mpi.world();
  const std::string chosen = chosen_name(commands);
  try {
    coatfft::agreed_refusal(world, [&] { COATFFT_REQUIRE(refusal.empty(), refusal); });
    std::string first = chosen;
    world.broadcast(first);
    coatfft::agreed_refusal(world, [&] {
      COATFFT_REQUIRE(chosen == first, "`", chosen, "`, where rank 0 runs `", first,
                      "`: every rank of an MPI launch runs the same command");
    });
  } catch (const coatfft::Error& e) {
    std::cerr << "coatfft: error: " << e.what() << '\n';
    return 2;
  }
  return run_chosen(commands);
}
#endif

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"coatfft: surface displacements and contact of coated elastic half-spaces"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("coatfft ") + COATFFT_VERSION);
  const std::vector<Command> commands{add_run(app), add_check(app),   add_validate_frf(app),
                                      add_frf(app), add_surface(app), add_topography(app)};
  // Under an MPI launcher rank 0 speaks for the run: the other ranks' messages (the same
  // refusals, or agreed ones that rank 0 prints naming the rank) are dropped.
  const auto launch = coatfft::detail::mpi_launch();
  if (launch.rank != 0) std::cerr.setstate(std::ios::failbit);
  std::string refusal = unknown_command(argc, argv);  // the command line's, one line
  if (refusal.empty()) {
    try {
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
      refusal = coatfft::detail::shorten(e.what(), 200) + " (see coatfft --help)";
    }
  }
  const std::string chosen = chosen_name(commands);
#ifdef COATFFT_WITH_MPI
  // MPI starts for the commands that run distributed, and for a command line that a rank refuses
  // (rank 0 then names that rank's refusal).
  if (launch.size > 1 && (!refusal.empty() || chosen == "surface" || chosen == "run"))
    return run_on_ranks(commands, refusal, argc, argv);
  const char* why = "does not run distributed yet";
#else
  const char* why = "runs distributed only in a build with COATFFT_MPI";
#endif
  // Several ranks: any other command would run whole on each, into the same output, so it is
  // refused before it reads anything (docs/scale.md).
  if (launch.size > 1 && refusal.empty())
    refusal =
        coatfft::detail::concat("started by an MPI launcher with ", launch.size, " ranks, but `",
                                chosen, "` ", why, " (docs/scale.md): run it without mpirun");
  if (!refusal.empty()) {
    std::cerr << "coatfft: error: " << refusal << '\n';
    return 2;
  }
  return run_chosen(commands);
}
