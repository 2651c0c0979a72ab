#pragma once
// A ParticleFrame as a vtkPolyData of vertices whose point and field arrays wrap the frame's
// buffers without copying (VTK never frees or writes them): the one builder for the VTP extracts
// and the Catalyst channel; or as a vtkUnstructuredGrid of vertex cells (the VTU extracts). Only
// for builds with ParaView's VTK.
#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "io/particle_frame.hpp"

namespace psph {

class ParticlePolyData {
 public:
  // Valid while `frame`'s buffers are alive and unchanged.
  vtkSmartPointer<vtkPolyData> wrap(const ParticleFrame& frame);
  vtkSmartPointer<vtkUnstructuredGrid> wrap_grid(const ParticleFrame& frame);

 private:
  vtkSmartPointer<vtkCellArray> verts_;  // rebuilt only when the particle count changes
  int verts_n_ = -1;
};

}  // namespace psph
