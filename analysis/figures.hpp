// The figures of `granshock fields`, drawn by Python scripts next to this file
// (plot_fields.py: the paper's Figs. 3-5 and the stagnation-line profiles;
// plot_detachment.py: Fig. 6) with matplotlib's Agg backend. The interpreter is
// $GRANSHOCK_PYTHON or /usr/bin/python3 (Debian's, which has python3-matplotlib and
// python3-h5py; another python3 first on PATH may lack them).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace granshock {

// The directory of the running program (empty where /proc cannot tell): an installed
// granshock finds its data in ../share/granshock from there.
std::filesystem::path program_directory();

// The interpreter the figures use.
std::filesystem::path plotting_python();

// The path of a figure script: found in $GRANSHOCK_SCRIPT_DIR, then in
// <directory of the program>/../share/granshock (an installed granshock), then in the
// source directory this library was built from. Throws UserError when none has it.
std::filesystem::path figure_script(const std::string& name);
// The same with another source directory, for scripts that live beside other code.
std::filesystem::path figure_script(const std::string& name,
                                    const std::filesystem::path& source_dir);

// Runs the plotting interpreter on `script` with `args` (no shell); throws UserError
// naming the script when it fails (its own message is on stderr).
void run_figure_script(const std::filesystem::path& script, const std::vector<std::string>& args);

// Throws UserError with the packages to install when the interpreter is missing or
// cannot import matplotlib, h5py and numpy.
void require_plotting_python();

// Writes figures_dir/{solid_fraction,temperature,mach,stagnation_profiles}.png from fields.h5.
void plot_run_figures(const std::filesystem::path& fields_h5,
                      const std::filesystem::path& figures_dir);
// The same for several runs, each a (fields.h5, figures directory) pair, in one interpreter.
void plot_run_figures(
    const std::vector<std::pair<std::filesystem::path, std::filesystem::path>>& runs);

// Writes png: delta/D against D/d for each Ma_inf, with error bars, from the table JSON of
// detachment_table.hpp.
void plot_detachment_figure(const std::filesystem::path& table_json,
                            const std::filesystem::path& png);

}  // namespace granshock
