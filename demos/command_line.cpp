// SPDX-License-Identifier: BSD-3-Clause
#include "command_line.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace lsr::demos {

namespace po = boost::program_options;

namespace {

constexpr unsigned kLineLength = 100;
constexpr unsigned kDescriptionColumn = 50;

std::string shown(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

CommandLine::CommandLine(std::string program, std::string version, std::string usage, std::string epilogue)
    : program_(std::move(program)), version_(std::move(version)), usage_(std::move(usage)),
      epilogue_(std::move(epilogue)) {
  groups_.emplace_back("general", kLineLength, kDescriptionColumn);
  groups_.back().add_options()("help,h", "this text")("version", "the version");
}

CommandLine& CommandLine::group(const std::string& caption) {
  groups_.emplace_back(caption, kLineLength, kDescriptionColumn);
  return *this;
}

po::options_description& CommandLine::current() { return groups_.back(); }

CommandLine& CommandLine::number(const std::string& name, const std::string& value_name, double default_value,
                                 double lo, double hi, bool whole, const std::string& help,
                                 std::function<void(double)> set) {
  current().add_options()(name.c_str(), po::value<std::string>()->value_name(value_name)->default_value(shown(default_value)),
                          help.c_str());
  conversions_.push_back({name, [this, name, lo, hi, whole, set](const std::string& text) {
                                 char* end = nullptr;
                                 const double v = std::strtod(text.c_str(), &end);
                                 const bool parsed = !text.empty() && end == text.c_str() + text.size();
                                 if (!parsed || !(v >= lo && v <= hi) || (whole && v != std::floor(v))) {
                                   fail("--" + name + " expects " + (whole ? "a whole number" : "a number") +
                                        " between " + shown(lo) + " and " + shown(hi) + ", got '" + text + "'");
                                 }
                                 set(v);
                               }});
  return *this;
}

CommandLine& CommandLine::text(const std::string& name, const std::string& value_name, std::string& target,
                               const std::string& help, std::vector<std::string> choices) {
  auto value = po::value<std::string>()->value_name(value_name);
  if (!target.empty()) value->default_value(target);
  current().add_options()(name.c_str(), value, help.c_str());
  conversions_.push_back({name, [this, name, &target, choices](const std::string& text) {
                                 if (!choices.empty() && std::find(choices.begin(), choices.end(), text) == choices.end()) {
                                   std::string list;
                                   for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
                                   fail("--" + name + " must be one of " + list + ", got '" + text + "'");
                                 }
                                 target = text;
                               }});
  return *this;
}

CommandLine& CommandLine::flag(const std::string& name, bool& target, const std::string& help) {
  current().add_options()(name.c_str(), po::bool_switch(&target), help.c_str());
  return *this;
}

std::string CommandLine::help() const {
  std::ostringstream s;
  // One description holding the groups aligns all of them on one column.
  po::options_description all(kLineLength, kDescriptionColumn);
  for (const auto& g : groups_) all.add(g);
  s << usage_ << all << '\n';
  s << epilogue_;
  return s.str();
}

void CommandLine::fail(const std::string& message) const {
  std::cerr << program_ << ": " << message << "\n(run " << program_ << " --help for the usage)\n";
  std::exit(2);
}

std::vector<std::string> CommandLine::parse(int argc, char** argv, std::size_t min_positional,
                                            std::size_t max_positional, const std::string& positional_names) {
  // Help and version win over any error elsewhere on the line.
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") break;
    if (a == "-h" || a == "--help") {
      std::cout << help();
      std::exit(0);
    }
    if (a == "--version") {
      std::cout << program_ << ' ' << version_ << '\n';
      std::exit(0);
    }
  }
  po::options_description all;
  for (const auto& g : groups_) all.add(g);
  std::vector<std::string> positional;
  all.add_options()("positional", po::value<std::vector<std::string>>(&positional));
  po::positional_options_description order;
  order.add("positional", -1);
  // No guessing of abbreviations: --res would otherwise silently mean --resolution.
  const int style = po::command_line_style::unix_style & ~po::command_line_style::allow_guessing;
  po::variables_map values;
  try {
    po::store(po::command_line_parser(argc, argv).options(all).positional(order).style(style).run(), values);
    po::notify(values);
  } catch (const po::error& e) {
    fail(e.what());
  }
  for (const auto& c : conversions_) {
    const auto it = values.find(c.name);
    if (it != values.end() && !it->second.defaulted()) c.apply(it->second.as<std::string>());
  }
  if (positional.size() < min_positional || positional.size() > max_positional) {
    fail("expected " + positional_names + ", got " + std::to_string(positional.size()) + " argument(s)");
  }
  return positional;
}

}  // namespace lsr::demos
