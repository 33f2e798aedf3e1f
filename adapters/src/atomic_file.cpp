// SPDX-License-Identifier: BSD-3-Clause
/// @file atomic_file.cpp
#include "lsrecon/adapters/atomic_file.h"

#include "lsrecon/core/errors.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace lsr {
namespace {

namespace fs = std::filesystem;

// Names this long or longer fail in every common file system (NAME_MAX).
constexpr std::size_t kMaxName = 255;
// What the temporary's name adds to the stem: ".partial-" and 6 characters.
constexpr std::size_t kSuffix = 15;

// Six characters that differ between calls and processes (uniqueness comes from O_EXCL).
std::string random_tag() {
  static std::atomic<unsigned long long> counter{0};
  static const char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  unsigned long long x = (unsigned long long)::getpid() * 0x9E3779B97F4A7C15ull ^
                         (unsigned long long)std::chrono::steady_clock::now().time_since_epoch().count() ^
                         (counter++ * 0xBF58476D1CE4E5B9ull);
  std::string tag;
  for (int i = 0; i < 6; ++i) {
    x ^= x >> 31;
    x *= 0x94D049BB133111EBull;
    tag += kAlphabet[(x >> 40) % 36];
  }
  return tag;
}

}  // namespace

StagedFile::StagedFile(const std::string& destination) : destination_(destination), target_(destination) {
  std::error_code e;
  // Through a symlink to its file: the link stays, the file it names is replaced.
  if (fs::is_symlink(destination, e) && fs::exists(destination, e)) target_ = fs::canonical(destination, e).string();
  const fs::path target(target_);
  const std::string name = target.filename().string();
  if (name.empty()) throw Error(destination + " names a folder, not a file", "name an output file");
  if (name.size() > kMaxName) {
    throw Error("the output name " + destination + " is longer than the file system allows (" + std::to_string(kMaxName) + " bytes)",
                "choose a shorter name");
  }
  // Keep the extension: writers pick the format from it (out.ply -> out.partial-x1y2z3.ply).
  const std::string ext = target.has_stem() && target.has_extension() ? target.extension().string() : "";
  const std::string stem = name.substr(0, std::min(name.size() - ext.size(), kMaxName - kSuffix - ext.size()));
  struct stat existing {};
  const bool exists = ::stat(target_.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string candidate = (target.parent_path() / (stem + ".partial-" + random_tag() + ext)).string();
    // O_EXCL: created here and now, never a file or symlink that was there before.
    const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0 && errno == EEXIST) continue;
    if (fd < 0) {
      throw Error("cannot create a file beside " + destination + " (" + std::strerror(errno) + ")",
                  "check that the output folder exists and is writable");
    }
    if (exists) (void)::fchmod(fd, existing.st_mode & 07777);
    ::close(fd);
    temporary_ = candidate;
    return;
  }
  throw Error("cannot create a temporary file beside " + destination, "remove stale *.partial-* files there");
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : destination_(std::move(other.destination_)), target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)), committed_(other.committed_) {
  other.committed_ = true;  // nothing left for it to remove
}

StagedFile::~StagedFile() {
  if (!committed_ && !temporary_.empty()) std::remove(temporary_.c_str());
}

void StagedFile::commit() {
  if (committed_) return;
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    throw Error("cannot move the finished file onto " + destination_ + " (" + std::strerror(errno) + ")",
                "check that the output folder exists and is writable");
  }
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  StagedFile file(path);
  write(file.temporary());
  file.commit();
}

}  // namespace lsr
