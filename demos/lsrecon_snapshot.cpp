// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_snapshot.cpp
/// @brief Renders meshes (.ply, .vtu) to a PNG, offscreen (run under xvfb-run), one viewport
/// per input with its name as a label:
///   lsrecon-snapshot OUTPUT.png INPUT... [--clip | --slice | --top | --below] [--columns N] [--width W] [--height H]
/// --clip cuts a volume mesh by the plane y = centre and shows the cut with its edges (the
/// grading of an adaptive mesh); --slice shows only the section by that plane (the elements'
/// shapes: those of an anisotropic mesh are long along the surface); --top looks down the z
/// axis, --below looks up at the underside. Flat (2D) data is seen from above. A PLY without
/// faces (a cloud) is drawn as its points, e.g. beside its reconstruction.
/// Back faces are blue: a closed surface that shows blue is oriented inwards there.
#include "command_line.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkCutter.h>
#include <vtkDataSet.h>
#include <vtkCellData.h>
#include <vtkDataSetMapper.h>
#include <vtkExtractGeometry.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPNGWriter.h>
#include <vtkPlane.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVertexGlyphFilter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct View {
  bool clip = false, slice = false, top = false, below = false, edges = false;
};

vtkSmartPointer<vtkDataSet> read(const std::string& path) {
  if (path.size() > 4 && path.substr(path.size() - 4) == ".ply") {
    vtkNew<vtkPLYReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    if (reader->GetOutput()->GetNumberOfCells() > 0) return vtkSmartPointer<vtkDataSet>(reader->GetOutput());
    vtkNew<vtkVertexGlyphFilter> points;  // a cloud: one vertex cell per point
    points->SetInputConnection(reader->GetOutputPort());
    points->Update();
    return vtkSmartPointer<vtkDataSet>(points->GetOutput());
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return vtkSmartPointer<vtkDataSet>(reader->GetOutput());
}

std::string label(const std::string& path) {
  std::string name = path.substr(path.find_last_of('/') + 1);
  return name.substr(0, name.find_last_of('.'));
}

void add_view(vtkRenderWindow* window, vtkDataSet* data, const std::string& title, const View& v, double x0,
              double y0, double x1, double y1) {
  vtkNew<vtkRenderer> renderer;
  renderer->SetViewport(x0, y0, x1, y1);
  renderer->SetBackground(1, 1, 1);
  window->AddRenderer(renderer);
  vtkNew<vtkTextActor> text;
  text->SetInput(title.c_str());
  text->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  text->GetTextProperty()->SetFontSize(18);
  text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  text->SetPosition(0.03, 0.03);
  renderer->AddActor2D(text);
  if (data->GetNumberOfCells() == 0) return;  // an empty result: just its label
  double b[6];
  data->GetBounds(b);
  vtkNew<vtkDataSetMapper> mapper;
  vtkNew<vtkActor> actor;
  const bool flat = b[5] - b[4] <= 1e-12 * std::max(b[1] - b[0], b[3] - b[2]);
  const bool regions = data->GetCellData()->HasArray("region");  // lsrecon --volume-mesh
  const bool cut = (v.clip || v.slice) && !flat;
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  plane->SetNormal(0, -1, 0);
  vtkNew<vtkExtractGeometry> clip;
  vtkNew<vtkCutter> section;
  if (cut && v.slice) {
    section->SetInputData(data);
    section->SetCutFunction(plane);
    mapper->SetInputConnection(section->GetOutputPort());
    actor->GetProperty()->SetEdgeVisibility(true);
    actor->GetProperty()->SetLineWidth(0.5);
  } else if (cut) {
    clip->SetInputData(data);
    clip->SetImplicitFunction(plane);
    clip->ExtractInsideOn();
    clip->ExtractBoundaryCellsOn();
    mapper->SetInputConnection(clip->GetOutputPort());
    actor->GetProperty()->SetEdgeVisibility(true);
    actor->GetProperty()->SetLineWidth(0.5);
  } else {
    mapper->SetInputData(data);
  }
  mapper->ScalarVisibilityOff();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.75, 0.55);
  vtkNew<vtkProperty> back;  // faces seen from behind (inward-oriented) show blue
  back->SetColor(0.45, 0.6, 0.9);
  actor->SetBackfaceProperty(back);
  if (data->GetCellType(0) == VTK_VERTEX) {  // a cloud, beside its reconstruction
    actor->GetProperty()->SetColor(0.2, 0.2, 0.3);
    actor->GetProperty()->SetPointSize(2.0);
    actor->GetProperty()->LightingOff();
  }
  if (v.edges) {
    actor->GetProperty()->SetEdgeVisibility(true);
    actor->GetProperty()->SetEdgeColor(0.35, 0.3, 0.2);
    actor->GetProperty()->SetLineWidth(0.5);
  }
  if (regions) {
    // Inside (1) blue, outside (2) sand, with the simplices' edges.
    vtkNew<vtkLookupTable> colours;
    colours->SetNumberOfTableValues(2);
    colours->SetTableValue(0, 0.45, 0.6, 0.9);
    colours->SetTableValue(1, 0.93, 0.87, 0.75);
    colours->Build();
    mapper->SetLookupTable(colours);
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray("region");
    mapper->SetScalarRange(1, 2);
    mapper->ScalarVisibilityOn();
    actor->GetProperty()->SetEdgeVisibility(true);
    actor->GetProperty()->SetLineWidth(0.5);
  } else if (flat) {
    actor->GetProperty()->SetColor(0.1, 0.2, 0.6);
    actor->GetProperty()->SetLineWidth(3.0);
    actor->GetProperty()->LightingOff();
  }
  renderer->AddActor(actor);
  renderer->ResetCamera();
  vtkCamera* camera = renderer->GetActiveCamera();
  if (cut) {
    camera->SetPosition(0.5 * (b[0] + b[1]), b[2] - 3 * (b[3] - b[2]), 0.5 * (b[4] + b[5]));
    camera->SetViewUp(0, 0, 1);
  } else if (!flat && !v.top) {
    camera->Elevation(v.below ? -30 : 30);
    camera->Azimuth(30);
  }
  renderer->ResetCamera();
}

}  // namespace

// VTK 9.1 renders through X only. Without a display the run starts itself again under xvfb-run
// (Debian's xvfb), once: what the help's "offscreen" promises.
void ensure_display(char** argv) {
  const char* display = std::getenv("DISPLAY");
  if ((display && *display) || std::getenv("LSRECON_SNAPSHOT_XVFB")) return;
  ::setenv("LSRECON_SNAPSHOT_XVFB", "1", 1);
  std::vector<char*> args = {const_cast<char*>("xvfb-run"), const_cast<char*>("-a")};
  for (char** a = argv; *a; ++a) args.push_back(*a);
  args.push_back(nullptr);
  ::execvp("xvfb-run", args.data());
  std::fprintf(stderr, "lsrecon-snapshot: no X display and no xvfb-run [hint: install xvfb (apt-get install xvfb) or set DISPLAY]\n");
  std::exit(1);
}

int main(int argc, char** argv) {
  ensure_display(argv);
  View v;
  int columns = 0, width = 0, height = 0;
  lsr::demos::CommandLine line("lsrecon-snapshot", LSRECON_VERSION,
                               "usage: lsrecon-snapshot OUTPUT.png INPUT.{ply,vtu}... [options]\n\n"
                               "Renders meshes (and .vtu volume results; a PLY without faces as its points) offscreen\n"
                               "to one PNG, one view per input (without an X display it runs itself under xvfb-run).\n");
  line.group("view")
      .flag("clip", v.clip, "cut volume meshes by the plane y = centre and show the cut with its edges")
      .flag("slice", v.slice, "show only the section of volume meshes by the plane y = centre, with its edges")
      .flag("top", v.top, "look down the z axis (flat, 2D data always is)")
      .flag("below", v.below, "look from below (the underside of a scan from above)")
      .flag("edges", v.edges, "draw the triangles' edges")
      .number("columns", "N", columns, 0, 100, "views per row; 0 = up to 4")
      .number("width", "W", width, 0, 20000, "image width in pixels; 0 = from the number of views")
      .number("height", "H", height, 0, 20000, "image height in pixels; 0 = from the number of views");
  std::vector<std::string> inputs = line.parse(argc, argv, 2, 1000, "OUTPUT.png and at least one INPUT");
  const std::string output = inputs.front();
  inputs.erase(inputs.begin());
  for (const auto& in : inputs) {
    if (!std::ifstream(in)) {
      std::fprintf(stderr, "lsrecon-snapshot: cannot read %s\n", in.c_str());
      return 1;
    }
  }
  const int n = int(inputs.size());
  if (columns <= 0) columns = std::min(n, 4);
  const int rows = (n + columns - 1) / columns;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width > 0 ? width : (n == 1 ? 1000 : 400 * columns), height > 0 ? height : (n == 1 ? 800 : 360 * rows));
  for (int k = 0; k < n; ++k) {
    const int r = k / columns, c = k % columns;
    add_view(window, read(inputs[k]), label(inputs[k]), v, double(c) / columns, 1.0 - double(r + 1) / rows,
             double(c + 1) / columns, 1.0 - double(r) / rows);
  }
  window->Render();
  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(window);
  image->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(output.c_str());
  writer->SetInputConnection(image->GetOutputPort());
  writer->Write();
  std::printf("wrote %s\n", output.c_str());
  return 0;
}
