// The OpenMesh mesh type used for import, export and half-edge queries.
#pragma once

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh> // for PolyMesh_ArrayKernelT

namespace meshpaint {

using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

} // namespace meshpaint
