// fooball-cli: the headless front end (DESIGN.md, "fooball-cli (headless)").

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

#include "capacity_command.h"
#include "compare_command.h"
#include "failure_map_command.h"
#include "fooball/scene_error.h"
#include "fooball/version.h"
#include "list_command.h"
#include "run_command.h"
#include "run_options.h"
#include "tradeoff_command.h"
#include "usage_error.h"

namespace {

using namespace fooball::cli;

constexpr const char* kProgramName = "fooball-cli";

/// Every failure is one line on stderr, so scripts and logs get a readable reason.
int reportError(const std::string& message, int exitCode) {
  std::cerr << kProgramName << ": error: " << message << '\n';
  return exitCode;
}

/// Declares `run`'s flags; the ones without a default are read back by readRunFlags.
struct RunFlags {
  std::string scenePath;
  double dt = 0.0;
  std::string substeps;
  std::string metricsPath;
  std::string savePath;
  CLI::Option* sceneFlag = nullptr;
  CLI::Option* dtFlag = nullptr;
  CLI::Option* substepsFlag = nullptr;
  CLI::Option* metricsFlag = nullptr;
  CLI::Option* saveFlag = nullptr;
};

void addRunFlags(CLI::App& run, RunOptions& options, RunFlags& flags) {
  flags.sceneFlag =
      run.add_option("--scene", flags.scenePath, "scene file (JSON) to run")->type_name("FILE");
  run.add_option("--preset", options.presetName, "built-in scene to run (see 'list')")
      ->type_name("NAME")
      ->capture_default_str()
      ->excludes(flags.sceneFlag);
  run.add_option("--backend", options.backendSpec,
                 "physics backend and its options, a run spec: NAME[:KEY=VALUE[,KEY=VALUE]...] "
                 "(see 'list')")
      ->type_name("SPEC")
      ->capture_default_str();
  run.add_option("--duration", options.duration,
                 "simulated time to run, in seconds (0: load and check the scene, step nothing, "
                 "and with --save write it back unchanged)")
      ->type_name("SECONDS")
      ->capture_default_str();
  flags.dtFlag =
      run.add_option("--dt", flags.dt,
                     "physics time step in seconds (default: the scene's dt, else 1/60 s)")
          ->type_name("SECONDS");
  flags.substepsFlag =
      run.add_option("--substeps", flags.substeps, "the same as --option substeps=N")
          ->type_name("N");
  run.add_option("--option", options.assignments, "set a backend option (repeatable)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  flags.metricsFlag =
      run.add_option("--metrics", flags.metricsPath, "write metrics rows to a CSV file")
          ->type_name("FILE.csv");
  run.add_option("--every", options.every, "steps between metrics rows")
      ->type_name("N")
      ->capture_default_str();
  flags.saveFlag = run.add_option("--save", flags.savePath, "save the final state as a scene file")
                       ->type_name("FILE.json");
  run.add_flag("--quiet", options.quiet, "print no summary and no progress");
}

void readRunFlags(const RunFlags& flags, RunOptions& options) {
  if (flags.sceneFlag->count() > 0) options.scenePath = flags.scenePath;
  if (flags.dtFlag->count() > 0) options.dt = flags.dt;
  if (flags.substepsFlag->count() > 0) options.substeps = flags.substeps;
  if (flags.metricsFlag->count() > 0) options.metricsPath = flags.metricsPath;
  if (flags.saveFlag->count() > 0) options.savePath = flags.savePath;
}

/// Declares `compare`'s flags; the ones without a default are read back by readCompareFlags.
struct CompareFlags {
  std::string scenePath;
  double dt = 0.0;
  std::string csvPath;
  std::string chartPath;
  CLI::Option* sceneFlag = nullptr;
  CLI::Option* dtFlag = nullptr;
  CLI::Option* csvFlag = nullptr;
  CLI::Option* chartFlag = nullptr;
};

void addCompareFlags(CLI::App& compare, CompareOptions& options, CompareFlags& flags) {
  flags.sceneFlag =
      compare.add_option("--scene", flags.scenePath, "scene file (JSON) to run")->type_name("FILE");
  compare.add_option("--preset", options.presetName, "built-in scene to run (see 'list')")
      ->type_name("NAME")
      ->capture_default_str()
      ->excludes(flags.sceneFlag);
  compare
      .add_option("--run", options.runs,
                  "a run: NAME[:KEY=VALUE[,KEY=VALUE]...], 2 to 8 times; the first is the "
                  "reference")
      ->type_name("SPEC")
      ->allow_extra_args(false);
  compare.add_option("--duration", options.duration, "simulated time to run, in seconds")
      ->type_name("SECONDS")
      ->capture_default_str();
  flags.dtFlag =
      compare
          .add_option("--dt", flags.dt,
                      "physics time step in seconds (default: the scene's dt, else 1/60 s)")
          ->type_name("SECONDS");
  compare.add_option("--every", options.every, "steps between CSV rows")
      ->type_name("N")
      ->capture_default_str();
  compare.add_flag("--baseline", options.baseline,
                   "add the chaos baseline: run 0 with every ball moved 1e-9 m");
  flags.csvFlag = compare.add_option("--csv", flags.csvPath, "write one row per run per sample")
                      ->type_name("FILE");
  flags.chartFlag = compare
                        .add_option("--chart", flags.chartPath,
                                    "draw divergence and energy residual against time (PNG)")
                        ->type_name("FILE.png");
  compare.add_flag("--quiet", options.quiet, "print no table and no progress");
}

void readCompareFlags(const CompareFlags& flags, CompareOptions& options) {
  if (flags.sceneFlag->count() > 0) options.scenePath = flags.scenePath;
  if (flags.dtFlag->count() > 0) options.dt = flags.dt;
  if (flags.csvFlag->count() > 0) options.csvPath = flags.csvPath;
  if (flags.chartFlag->count() > 0) options.chartPath = flags.chartPath;
}

/// Declares `capacity`'s flags; the optional paths are read back by readCapacityFlags.
struct CapacityFlags {
  std::string csvPath;
  std::string chartPath;
  CLI::Option* csvFlag = nullptr;
  CLI::Option* chartFlag = nullptr;
};

void addCapacityFlags(CLI::App& capacity, CapacityOptions& options, CapacityFlags& flags) {
  capacity
      .add_option("--backend", options.backends,
                  "backend to measure, with its own options (repeatable; default all), e.g. "
                  "chipmunk:spatial_hash=1")
      ->type_name("SPEC")
      ->allow_extra_args(false);
  capacity.add_option("--budget-ms", options.budgetMs, "time one step may take, in ms")
      ->type_name("MS")
      ->default_str("16.67");
  capacity
      .add_option("--packing-fraction", options.packingFraction,
                  "share of the box the standard gas covers")
      ->type_name("PHI")
      ->capture_default_str();
  capacity
      .add_option("--warm-up", options.warmUpSeconds,
                  "simulated seconds each ball count runs untimed first, so the gas is timed "
                  "thermalised")
      ->type_name("SECONDS")
      ->capture_default_str();
  capacity.add_option("--steps", options.steps, "timed steps per ball count (the median counts)")
      ->type_name("K")
      ->capture_default_str();
  capacity.add_option("--time-limit", options.timeLimitSeconds, "seconds per backend, at most")
      ->type_name("SECONDS")
      ->capture_default_str();
  capacity
      .add_option("--option", options.assignments,
                  "set a backend option on every backend that has it (repeatable), e.g. "
                  "substeps=1")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  flags.csvFlag = capacity.add_option("--csv", flags.csvPath, "write backend,balls,median_step_ms")
                      ->type_name("FILE");
  flags.chartFlag =
      capacity.add_option("--chart", flags.chartPath, "draw step time against ball count (PNG)")
          ->type_name("FILE.png");
  capacity.add_flag("--quiet", options.quiet, "print no table and no progress");
}

void readCapacityFlags(const CapacityFlags& flags, CapacityOptions& options) {
  if (flags.csvFlag->count() > 0) options.csvPath = flags.csvPath;
  if (flags.chartFlag->count() > 0) options.chartPath = flags.chartPath;
}

/// Declares `tradeoff`'s flags; the optional paths are read back by readTradeoffFlags.
struct TradeoffFlags {
  std::string scenePath;
  std::string csvPath;
  std::string chartPath;
  CLI::Option* sceneFlag = nullptr;
  CLI::Option* csvFlag = nullptr;
  CLI::Option* chartFlag = nullptr;
};

void addTradeoffFlags(CLI::App& tradeoff, TradeoffOptions& options, TradeoffFlags& flags) {
  flags.sceneFlag =
      tradeoff.add_option("--scene", flags.scenePath, "scene file (JSON) to measure on")
          ->type_name("FILE");
  tradeoff.add_option("--preset", options.presetName, "built-in scene to measure on (see 'list')")
      ->type_name("NAME")
      ->capture_default_str()
      ->excludes(flags.sceneFlag);
  tradeoff
      .add_option("--backend", options.backends,
                  "backend to measure, with its own options (repeatable; default all), e.g. "
                  "chipmunk:spatial_hash=1")
      ->type_name("SPEC")
      ->allow_extra_args(false);
  tradeoff
      .add_option("--duration", options.duration,
                  "simulated seconds per run (cost, energy, momentum, overlap)")
      ->type_name("SECONDS")
      ->capture_default_str();
  tradeoff
      .add_option("--compare-at", options.compareAt,
                  "simulated second at which positions are compared with the exact backend's")
      ->type_name("SECONDS")
      ->capture_default_str();
  flags.csvFlag =
      tradeoff.add_option("--csv", flags.csvPath, "write one row per backend and setting")
          ->type_name("FILE");
  flags.chartFlag =
      tradeoff.add_option("--chart", flags.chartPath, "draw cost against errors (PNG)")
          ->type_name("FILE.png");
  tradeoff.add_flag("--quiet", options.quiet, "print no table and no progress");
}

void readTradeoffFlags(const TradeoffFlags& flags, TradeoffOptions& options) {
  if (flags.sceneFlag->count() > 0) options.scenePath = flags.scenePath;
  if (flags.csvFlag->count() > 0) options.csvPath = flags.csvPath;
  if (flags.chartFlag->count() > 0) options.chartPath = flags.chartPath;
}

/// Declares `failure-map`'s flags; the optional paths are read back by readFailureMapFlags.
struct FailureMapFlags {
  std::string csvPath;
  std::string chartDir;
  CLI::Option* csvFlag = nullptr;
  CLI::Option* chartDirFlag = nullptr;
};

void addFailureMapFlags(CLI::App& failureMap, FailureMapOptions& options, FailureMapFlags& flags) {
  failureMap
      .add_option("--backend", options.backends, "backend to sweep (repeatable; default all)")
      ->type_name("NAME")
      ->allow_extra_args(false);
  failureMap
      .add_option("--sweep", options.sweeps,
                  "sweep to run (repeatable; default all): tunnelling, mass-ratio, cradle, "
                  "packing, scale, pile")
      ->type_name("NAME")
      ->allow_extra_args(false);
  flags.csvFlag =
      failureMap.add_option("--csv", flags.csvPath, "write one row per scene of every sweep")
          ->type_name("FILE");
  flags.chartDirFlag =
      failureMap
          .add_option("--chart-dir", flags.chartDir, "draw failure-<sweep>.png into this directory")
          ->type_name("DIR");
  failureMap.add_flag("--quick", options.quick, "coarser grids and shorter scenes");
  failureMap.add_flag("--quiet", options.quiet, "print no table and no progress");
}

void readFailureMapFlags(const FailureMapFlags& flags, FailureMapOptions& options) {
  if (flags.csvFlag->count() > 0) options.csvPath = flags.csvPath;
  if (flags.chartDirFlag->count() > 0) options.chartDir = flags.chartDir;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"FooBall: bouncing balls on interchangeable physics backends, headless.",
               kProgramName};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string(fooball::kVersionLine),
                       "print the version and exit");
  app.footer("Exit codes: 0 ok, 2 bad arguments or bad scene, 1 any other failure.");
  CLI::App* list = app.add_subcommand("list", "list the backends with their options, and presets");
  CLI::App* run = app.add_subcommand("run", "run a scene and report energy and momentum");
  CLI::App* compare = app.add_subcommand(
      "compare", "run several methods on one scene in lockstep and measure how they diverge");
  CLI::App* capacity = app.add_subcommand(
      "capacity", "find how many balls each backend steps within a frame budget");
  CLI::App* tradeoff =
      app.add_subcommand("tradeoff", "measure each backend's cost against its errors");
  CLI::App* failureMap = app.add_subcommand(
      "failure-map", "find where each backend starts to fail (docs/accuracy.md)");

  RunOptions runOptions;
  RunFlags runFlags;
  addRunFlags(*run, runOptions, runFlags);
  CompareOptions compareOptions;
  CompareFlags compareFlags;
  addCompareFlags(*compare, compareOptions, compareFlags);
  CapacityOptions capacityOptions;
  CapacityFlags capacityFlags;
  addCapacityFlags(*capacity, capacityOptions, capacityFlags);
  TradeoffOptions tradeoffOptions;
  TradeoffFlags tradeoffFlags;
  addTradeoffFlags(*tradeoff, tradeoffOptions, tradeoffFlags);
  FailureMapOptions failureMapOptions;
  FailureMapFlags failureMapFlags;
  addFailureMapFlags(*failureMap, failureMapOptions, failureMapFlags);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version arrive as "success" errors; CLI11 prints them. Real errors get our one
    // line instead of CLI11's help dump.
    if (error.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(error);
    // CLI11 says only "A subcommand is required" for a word that names none: name the word.
    if (argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty()) {
      std::string known;
      for (const CLI::App* subcommand : app.get_subcommands({}))
        known += (known.empty() ? "" : ", ") + subcommand->get_name();
      return reportError("unknown command '" + std::string(argv[1]) + "' (known: " + known + ")",
                         kExitBadInput);
    }
    return reportError(std::string(error.what()) + " (see '" + kProgramName + " --help')",
                       kExitBadInput);
  }

  try {
    if (list->parsed()) {
      printList(std::cout);
    } else if (compare->parsed()) {
      readCompareFlags(compareFlags, compareOptions);
      compareCommand(compareOptions, std::cout);
    } else if (capacity->parsed()) {
      readCapacityFlags(capacityFlags, capacityOptions);
      capacityCommand(capacityOptions, std::cout);
    } else if (failureMap->parsed()) {
      readFailureMapFlags(failureMapFlags, failureMapOptions);
      failureMapCommand(failureMapOptions, std::cout);
    } else if (tradeoff->parsed()) {
      readTradeoffFlags(tradeoffFlags, tradeoffOptions);
      tradeoffCommand(tradeoffOptions, std::cout);
    } else {
      readRunFlags(runFlags, runOptions);
      runCommand(runOptions, std::cout);
    }
    std::cout.flush();
    if (!std::cout) return reportError("writing to standard output failed", kExitFailure);
  } catch (const UsageError& error) {
    return reportError(error.what(), kExitBadInput);
  } catch (const fooball::SceneError& error) {
    return reportError(error.what(), kExitBadInput);
  } catch (const std::invalid_argument& error) {
    return reportError(error.what(), kExitBadInput);
  } catch (const std::exception& error) {
    return reportError(error.what(), kExitFailure);
  }
  return kExitOk;
}
