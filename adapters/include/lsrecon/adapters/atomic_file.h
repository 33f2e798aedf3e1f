// SPDX-License-Identifier: BSD-3-Clause
/// @file atomic_file.h
/// @brief Writing a file so that a failure never leaves it half-written or clobbers an
/// existing one: write a temporary beside it, then rename it over the destination.
#pragma once

#include <functional>
#include <string>

namespace lsr {

/// @brief A file being written: a fresh temporary beside its destination, moved onto it by
/// commit() and removed otherwise (destruction without commit, e.g. on an error).
/// @note The temporary, "<stem>.partial-XXXXXX<.ext>" in the destination's folder (its
/// extension kept, so writers that choose the format by extension still do), is created with
/// O_EXCL: never an existing file, nor a symlink planted under that name. A destination that is
/// a symlink stays one: the file it points to is replaced. An existing destination keeps its
/// permission bits.
class StagedFile {
 public:
  /// @throw lsr::Error if the temporary cannot be created (the folder is missing or not
  /// writable, or the destination's name is longer than the file system allows).
  explicit StagedFile(const std::string& destination);
  ~StagedFile();
  StagedFile(StagedFile&& other) noexcept;
  StagedFile& operator=(StagedFile&& other) = delete;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  /// @brief The path to write to (it exists, empty).
  const std::string& temporary() const { return temporary_; }
  /// @brief The path as given.
  const std::string& destination() const { return destination_; }
  /// @brief Renames the temporary onto the destination.
  /// @throw lsr::Error if the rename fails (the temporary is then removed).
  void commit();

 private:
  std::string destination_, target_, temporary_;
  bool committed_ = false;
};

/// @brief Calls write(temporary_path) on a StagedFile of path, then commits it. If write throws
/// or the rename fails, the temporary is removed, path is left as it was, and the exception
/// propagates (write's own as is).
void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& write);

}  // namespace lsr
