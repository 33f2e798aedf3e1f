// SPDX-License-Identifier: BSD-3-Clause
/// @file command_line.h
/// @brief One way to declare a command line for every executable here: typed, range-checked
/// options in help groups, positional arguments, `--opt VALUE` and `--opt=VALUE`, -h/--help and
/// --version. The help text, defaults included, is generated from the declarations, so a default
/// is written once (for the solver: the lsr::ReconstructionOptions object the core documents).
///
/// Boost.Program_options does the parsing: it comes with PCL (libpcl-dev depends on
/// libboost-all-dev), so it adds no package. Numbers are converted here rather than by
/// boost::lexical_cast so that every bad value gets the same message: the option, what it expects
/// and what it got ("--max-iterations expects a whole number between 1 and 1e+07, got '2.7'").
#pragma once

#include <boost/program_options.hpp>

#include <functional>
#include <string>
#include <vector>

namespace lsr::demos {

class CommandLine {
 public:
  /// @param usage  printed above the options by --help (synopsis and what the program does)
  /// @param epilogue  printed below them (exit statuses, notes)
  CommandLine(std::string program, std::string version, std::string usage, std::string epilogue = "");

  /// Options declared after this call are listed under this caption.
  CommandLine& group(const std::string& caption);

  /// A number in [lo, hi], a whole one if `whole`; `shown` is the default printed by --help.
  CommandLine& number(const std::string& name, const std::string& value_name, double shown, double lo, double hi,
                      bool whole, const std::string& help, std::function<void(double)> set);
  /// The same, stored in `target`, whose current value is the default.
  template <class T>
  CommandLine& number(const std::string& name, const std::string& value_name, T& target, double lo, double hi,
                      const std::string& help) {
    return number(name, value_name, double(target), lo, hi, std::is_integral_v<T>, help,
                  [&target](double v) { target = T(v); });
  }
  /// A string; if `choices` is not empty it must be one of them.
  CommandLine& text(const std::string& name, const std::string& value_name, std::string& target,
                    const std::string& help, std::vector<std::string> choices = {});
  /// An option without a value; `target` becomes true when it is given.
  CommandLine& flag(const std::string& name, bool& target, const std::string& help);

  /// Parses argv. --help and --version print and exit 0; any error exits 2 through fail().
  /// Returns the positional arguments, of which there must be between min and max.
  std::vector<std::string> parse(int argc, char** argv, std::size_t min_positional, std::size_t max_positional,
                                 const std::string& positional_names);

  /// "program: message", a pointer to --help, exit status 2.
  [[noreturn]] void fail(const std::string& message) const;

  std::string help() const;

 private:
  boost::program_options::options_description& current();

  // A value's check and conversion, run after parsing in declaration order.
  struct Conversion {
    std::string name;
    std::function<void(const std::string&)> apply;
  };

  std::string program_, version_, usage_, epilogue_;
  std::vector<boost::program_options::options_description> groups_;
  std::vector<Conversion> conversions_;
};

}  // namespace lsr::demos
