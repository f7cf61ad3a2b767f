// Small meshes made in code for the tests, each exercising one case of the
// Catmull-Clark rules.
#pragma once

#include "mesh/base_mesh.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint::test {

BaseMesh tetrahedron();
BaseMesh cube();
//! Closed: triangles, quads and pentagons together (a pentagonal prism with
//! one side split into two triangles).
BaseMesh mixed_polygons();
//! Closed genus-2 surface: a plate of 3x5 unit cubes with two cells removed.
BaseMesh genus_two();
//! Open 3x3 quad grid: boundary curves and four sharp one-face corners.
BaseMesh open_grid();
//! Open triangle fan of 5 triangles around a boundary vertex (a boundary
//! vertex with more than two faces) plus a quad.
BaseMesh open_fan();
//! Pyramid over an n-gon: an apex of valence n and an n-sided face.
BaseMesh high_valence(int n = 12);
//! Two cubes that do not touch: several components.
BaseMesh two_components();

//! A flat, evenly spaced n x n grid of unit quads in the z = 0 plane (an
//! affine control net), corner at the origin.
BaseMesh flat_grid(int n);

//! A cube of 6 x n x n quads pushed onto the unit sphere, with a
//! deterministic radial noise of relative amplitude `noise`.
BaseMesh noisy_sphere(int n, float noise);

//! `mesh` with every face's corners in reverse order: its faces wound
//! inwards where they were wound outwards (as some scans come).
BaseMesh wound_inwards(const BaseMesh& mesh);

//! Every shape above, by name.
std::vector<std::string> shape_names();
BaseMesh shape(const std::string& name);

//! Path of a scan fetched by the set-up script (data/scans/NAME), or "" when
//! it is not there.
std::string scan_path(const std::string& file);

} // namespace meshpaint::test
