// SPDX-License-Identifier: BSD-3-Clause
/// @file lsrecon_snapshot.cpp
/// @brief Renders a .vtu written by lsrecon to a PNG, offscreen (run under xvfb-run):
///   lsrecon-snapshot INPUT.vtu OUTPUT.png [--clip | --top]
/// --clip cuts a volume mesh by the plane y = centre and shows the cut with its edges, which
/// makes the grading of an adaptive mesh visible; --top looks down the z axis. Flat (2D) data
/// is always seen from above.
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataSetMapper.h>
#include <vtkExtractGeometry.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlane.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: lsrecon-snapshot INPUT.vtu OUTPUT.png [--clip | --top]\n");
    return 2;
  }
  const std::string input = argv[1];
  const std::string output = argv[2];
  const bool clip = argc > 3 && std::string(argv[3]) == "--clip";
  const bool top = argc > 3 && std::string(argv[3]) == "--top";
  if (!std::ifstream(input)) {
    std::fprintf(stderr, "lsrecon-snapshot: cannot read %s\n", input.c_str());
    return 1;
  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(input.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (grid->GetNumberOfCells() == 0) {
    std::fprintf(stderr, "lsrecon-snapshot: %s holds no cells\n", input.c_str());
    return 1;
  }
  double b[6];
  grid->GetBounds(b);

  vtkNew<vtkDataSetMapper> mapper;
  vtkNew<vtkActor> actor;
  if (clip) {
    // Keep the cells behind the plane y = centre: the cut face shows the refinement.
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
    plane->SetNormal(0, -1, 0);
    vtkNew<vtkExtractGeometry> cut;
    cut->SetInputData(grid);
    cut->SetImplicitFunction(plane);
    cut->ExtractInsideOn();
    cut->ExtractBoundaryCellsOn();
    mapper->SetInputConnection(cut->GetOutputPort());
    actor->GetProperty()->SetEdgeVisibility(true);
    actor->GetProperty()->SetLineWidth(0.5);
  } else {
    mapper->SetInputData(grid);
  }
  mapper->ScalarVisibilityOff();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.85, 0.75, 0.55);
  const bool flat = b[5] - b[4] <= 1e-12 * std::max(b[1] - b[0], b[3] - b[2]);
  if (flat) {  // 2D curves: dark, thick lines seen from above
    actor->GetProperty()->SetColor(0.1, 0.2, 0.6);
    actor->GetProperty()->SetLineWidth(3.0);
    actor->GetProperty()->LightingOff();
  }

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->SetBackground(1, 1, 1);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(1000, 800);
  renderer->ResetCamera();
  const bool oblique = !clip && !flat && !top;
  renderer->GetActiveCamera()->Elevation(oblique ? 30 : 0);
  renderer->GetActiveCamera()->Azimuth(oblique ? 30 : 0);
  if (clip) renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  if (clip) renderer->GetActiveCamera()->SetPosition(0.5 * (b[0] + b[1]), b[2] - 3 * (b[3] - b[2]), 0.5 * (b[4] + b[5]));
  renderer->ResetCamera();
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
