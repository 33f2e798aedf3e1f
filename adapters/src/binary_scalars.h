// SPDX-License-Identifier: BSD-3-Clause
/// @file binary_scalars.h
/// @brief The numeric types of PLY properties and PCD fields, decoded from raw bytes of either
/// byte order into double (internal to the point readers).
#pragma once

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace lsr::adapters::detail {

/// @brief A numeric type: whether it is a float, signed, and how many bytes it takes.
struct ScalarType {
  enum Kind : std::uint8_t { signed_integer, unsigned_integer, floating };
  Kind kind = floating;
  int bytes = 0;  ///< 1, 2, 4 or 8 (floats: 4 or 8); 0 for none
  bool valid() const { return bytes == 1 || bytes == 2 || bytes == 4 || bytes == 8; }
};

inline bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// @brief The value of `type` stored at `at` (any alignment), `swap` if its byte order is not
/// the host's.
inline double decode_scalar(const unsigned char* at, ScalarType type, bool swap) {
  unsigned char b[8];
  for (int i = 0; i < type.bytes; ++i) b[i] = swap ? at[type.bytes - 1 - i] : at[i];
  switch (type.kind) {
    case ScalarType::floating:
      if (type.bytes == 4) {
        float f;
        std::memcpy(&f, b, 4);
        return double(f);
      } else {
        double d;
        std::memcpy(&d, b, 8);
        return d;
      }
    case ScalarType::signed_integer: {
      std::int64_t v = 0;
      if (type.bytes == 1) { std::int8_t x; std::memcpy(&x, b, 1); v = x; }
      if (type.bytes == 2) { std::int16_t x; std::memcpy(&x, b, 2); v = x; }
      if (type.bytes == 4) { std::int32_t x; std::memcpy(&x, b, 4); v = x; }
      if (type.bytes == 8) { std::memcpy(&v, b, 8); }
      return double(v);
    }
    case ScalarType::unsigned_integer: {
      std::uint64_t v = 0;
      if (type.bytes == 1) { std::uint8_t x; std::memcpy(&x, b, 1); v = x; }
      if (type.bytes == 2) { std::uint16_t x; std::memcpy(&x, b, 2); v = x; }
      if (type.bytes == 4) { std::uint32_t x; std::memcpy(&x, b, 4); v = x; }
      if (type.bytes == 8) { std::memcpy(&v, b, 8); }
      return double(v);
    }
  }
  return 0.0;
}

/// @brief A token of text as a number (strtod: also "nan" and "inf"); false unless the whole
/// token is one (a NUL inside it included).
inline bool parse_number(const std::string& token, double& value) {
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

/// @brief A value read from text, rounded as the declared type stores it (a float property holds
/// a float, whatever digits the text carries), as a binary file of that type would give it.
inline double as_declared(double value, ScalarType type) {
  return type.kind == ScalarType::floating && type.bytes == 4 ? double(float(value)) : value;
}

}  // namespace lsr::adapters::detail
