// SPDX-License-Identifier: BSD-3-Clause
/// @file atomic_file.h
/// @brief Writing a file so that a failure never leaves it half-written or clobbers an
/// existing one: write a temporary beside it, then rename over it.
#pragma once

#include <functional>
#include <string>

namespace lsr {

/// @brief Calls write(temporary_path) (path with ".partial" before its extension, so that
/// format detection by extension still works), then renames the temporary onto path. If write throws
/// or the rename fails, the temporary is removed, path is left as it was, and lsr::Error is
/// thrown (write's own exception is rethrown as is).
void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& write);

}  // namespace lsr
