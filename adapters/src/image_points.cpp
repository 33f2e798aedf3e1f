// SPDX-License-Identifier: BSD-3-Clause
/// @file image_points.cpp
/// PNG through libpng's simplified API, which reports a corrupt file as an error; VTK 9.1's
/// PNG reader crashed on one (fuzzing: a wrong IHDR length). Netpbm is read here: a few lines.
#include "lsrecon/adapters/image_points.h"

#include "lsrecon/adapters/file_header_checks.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/errors.h"

#include <png.h>

#include <cstdint>
#include <fstream>
#include <vector>

namespace lsr::adapters {
namespace {

const char* const kHint = "use a valid PGM / PPM / PBM or PNG file";

// Grey levels in [0, 1], row by row from the top.
struct GreyImage {
  std::size_t width = 0, height = 0;
  std::vector<float> grey;
};

GreyImage read_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) {
    throw Error("cannot read the PNG image " + path + " (" + image.message + ")", kHint);
  }
  image.format = PNG_FORMAT_GRAY;
  std::vector<png_byte> pixels(PNG_IMAGE_SIZE(image));
  const png_color white{255, 255, 255};  // transparent pixels are background
  if (!png_image_finish_read(&image, &white, pixels.data(), 0, nullptr)) {
    const std::string why = image.message;
    png_image_free(&image);
    throw Error("cannot read the PNG image " + path + " (" + why + ")", kHint);
  }
  GreyImage g{image.width, image.height, {}};
  g.grey.reserve(pixels.size());
  for (png_byte p : pixels) g.grey.push_back(float(p) / 255.0f);
  return g;
}

// Netpbm P1-P6 (the sizes were checked against the file by check_declared_size).
GreyImage read_pnm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  auto token = [&]() {
    std::string t;
    while (in >> t && t[0] == '#') std::getline(in, t);
    if (!in) throw Error("truncated image " + path, kHint);
    return t;
  };
  const std::string magic = token();
  const char kind = magic.size() == 2 && magic[0] == 'P' ? magic[1] : '0';
  if (kind < '1' || kind > '6') throw Error(path + " is not a PBM / PGM / PPM image", kHint);
  GreyImage g;
  g.width = std::stoul(token());
  g.height = std::stoul(token());
  const bool bitmap = kind == '1' || kind == '4';
  const unsigned long maxval = bitmap ? 1 : std::stoul(token());
  if (maxval == 0 || maxval > 65535) throw Error(path + ": maximum grey value " + std::to_string(maxval), kHint);
  const int channels = (kind == '3' || kind == '6') ? 3 : 1;
  const bool binary = kind >= '4';
  if (binary) in.get();  // the single whitespace before the raster
  auto sample = [&]() -> double {
    if (!binary) return double(std::stoul(token()));
    unsigned char b[2] = {0, 0};
    if (!in.read(reinterpret_cast<char*>(b), maxval > 255 ? 2 : 1)) throw Error("truncated image " + path, kHint);
    return maxval > 255 ? double(b[0] * 256 + b[1]) : double(b[0]);
  };
  g.grey.reserve(g.width * g.height);
  for (std::size_t y = 0; y < g.height; ++y) {
    std::vector<unsigned char> row;
    if (kind == '4') {  // 8 pixels per byte, rows padded to bytes
      row.resize((g.width + 7) / 8);
      if (!in.read(reinterpret_cast<char*>(row.data()), std::streamsize(row.size()))) throw Error("truncated image " + path, kHint);
    }
    for (std::size_t x = 0; x < g.width; ++x) {
      if (kind == '4') {
        g.grey.push_back((row[x / 8] >> (7 - x % 8)) & 1 ? 0.0f : 1.0f);
      } else if (kind == '1') {
        g.grey.push_back(sample() > 0.0 ? 0.0f : 1.0f);  // 1 is black
      } else {
        double sum = 0.0;
        for (int c = 0; c < channels; ++c) sum += sample();
        g.grey.push_back(float(sum / (channels * double(maxval))));
      }
    }
  }
  return g;
}

}  // namespace

Points<2> read_image_points(const std::string& path) {
  lsr::adapters::check_declared_size(path);
  GreyImage image;
  try {
    image = lsr::adapters::file_extension(path) == "png" ? read_png(path) : read_pnm(path);
  } catch (const std::logic_error&) {  // stoul on a malformed header
    throw Error("cannot read the image header of " + path, kHint);
  }
  Points<2> points;
  for (std::size_t y = 0; y < image.height; ++y) {
    for (std::size_t x = 0; x < image.width; ++x) {
      // Pixel centres, y up (the first row is the top).
      if (image.grey[y * image.width + x] < 0.5f) points.emplace_back(double(x) + 0.5, double(image.height - 1 - y) + 0.5);
    }
  }
  if (points.empty()) throw Error("the image " + path + " has no dark pixel", "data points are pixels darker than 50% grey");
  return points;
}

}  // namespace lsr::adapters
