#pragma once
// The turtle's machinery, shared by the three files that make it:
//   core/turtle/turtle.cpp           the string turtle: reads a module string, one module at a time
//   core/turtle/turtle_tree.cpp      the tree-drawing optimizer: draws a D0L string from its derivation
//                                    tree, each repeated subtree once, placed by a transform
//   core/turtle/turtle_geometry.cpp  the geometry they emit beyond stems: polygons, surfaces, discs,
//                                    generalized cylinders, automatic widths and bounds
// They include this header, which brings in its parts, each a header by role:
//   turtle_state.hpp    the actions, the frame (SIMD vectors) and the state pushed at brackets
//   turtle_buffers.hpp  the segment writer (streaming stores) and the tree turtle's workspace
//   turtle_class.hpp    the Turtle class: its members, and the declarations of what the files
//                       above and turtle_step.hpp define
//   turtle_step.hpp     the per-module step (apply) with its turns, stems and tropism: the hot
//                       code, defined inline so that both readers inline it
#include "core/turtle/turtle_buffers.hpp"
#include "core/turtle/turtle_class.hpp"
#include "core/turtle/turtle_state.hpp"
#include "core/turtle/turtle_step.hpp"
