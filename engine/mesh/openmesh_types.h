// The OpenMesh mesh type used for import, export and half-edge queries.
#pragma once

#include "mesh/base_mesh.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh> // for PolyMesh_ArrayKernelT

namespace meshpaint {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

//! The base mesh in OpenMesh's half-edge structure (same vertex and face order).
PolyMesh to_openmesh(const BaseMesh& mesh);

} // namespace meshpaint
