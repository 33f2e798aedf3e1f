// SPDX-License-Identifier: BSD-3-Clause
/// @file image_points.cpp
#include "image_points.h"

#include "lsrecon/adapters/file_header_checks.h"
#include "lsrecon/core/errors.h"

#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNMReader.h>
#include <vtkSmartPointer.h>

#include <fstream>

namespace lsr::demos {

Points<2> read_image_points(const std::string& path) {
  lsr::adapters::check_declared_size(path);
  const bool png = path.size() > 4 && path.substr(path.size() - 4) == ".png";
  vtkSmartPointer<vtkImageReader2> reader;
  if (png) {
    reader = vtkSmartPointer<vtkPNGReader>::New();
  } else {
    reader = vtkSmartPointer<vtkPNMReader>::New();
  }
  if (!reader->CanReadFile(path.c_str())) {
    throw Error("cannot read the image " + path, "use a valid PGM / PPM or PNG file");
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  const int channels = image->GetNumberOfScalarComponents();
  Points<2> points;
  for (int y = 0; y < dims[1]; ++y) {
    for (int x = 0; x < dims[0]; ++x) {
      double grey = 0.0;
      for (int c = 0; c < std::min(channels, 3); ++c) grey += image->GetScalarComponentAsDouble(x, y, 0, c);
      grey /= std::min(channels, 3);
      if (grey < 128.0) points.emplace_back(x + 0.5, y + 0.5);  // VTK's origin is bottom-left: y up
    }
  }
  if (points.empty()) throw Error("the image " + path + " has no dark pixel", "data points are pixels darker than 50% grey");
  return points;
}

}  // namespace lsr::demos
