// SPDX-License-Identifier: BSD-3-Clause
/// @file staged_outputs.cpp
#include "staged_outputs.h"

#include "lsrecon/core/errors.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>

namespace lsr::demos {

namespace fs = std::filesystem;

std::string StagedOutputs::stage(const std::string& file) {
  const fs::path out(file);
  const fs::path dir = out.has_parent_path() ? out.parent_path() : fs::path(".");
  std::error_code e;
  if (!fs::is_directory(dir, e)) throw Error("the output directory " + dir.string() + " does not exist", "create it first");
  if (::access(dir.c_str(), W_OK) != 0) {
    throw Error("cannot write in " + dir.string() + " (permission denied)", "write the output elsewhere");
  }
  if (fs::is_directory(out, e)) throw Error(file + " is a directory", "name an output file");
  if (!input_.empty() && fs::exists(out, e) && fs::equivalent(input_, out, e)) {
    throw Error(file + " is the input file", "name another output file; the input would be overwritten");
  }
  // Two outputs onto one file: the later would replace the earlier (a report over the mesh).
  const fs::path resolved = fs::weakly_canonical(fs::absolute(out, e), e);
  const auto same = std::find(resolved_.begin(), resolved_.end(), resolved);
  if (same != resolved_.end()) {
    throw Error(file + " is named for two outputs (" + files_[std::size_t(same - resolved_.begin())].destination() + ")",
                "give each output (the result, --report, --save-points, --volume-mesh, --levels' files) its own name");
  }
  files_.emplace_back(file);
  resolved_.push_back(resolved);
  return files_.back().temporary();
}

std::string StagedOutputs::in_destination_terms(std::string message) {
  // Each ".partial-" and the 6 letters or digits after it go (std::regex would do it, but GCC
  // 12 warns inside <regex>).
  const std::string tag = ".partial-";
  for (std::size_t at = message.find(tag); at != std::string::npos; at = message.find(tag, at)) {
    std::size_t end = at + tag.size();
    while (end < message.size() && end < at + tag.size() + 6 &&
           (std::islower(static_cast<unsigned char>(message[end])) || std::isdigit(static_cast<unsigned char>(message[end])))) {
      ++end;
    }
    if (end == at + tag.size() + 6) {
      message.erase(at, end - at);
    } else {
      at = end;
    }
  }
  return message;
}

void StagedOutputs::commit_all() {
  for (StagedFile& f : files_) f.commit();
}

}  // namespace lsr::demos
