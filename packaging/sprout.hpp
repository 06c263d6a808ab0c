#pragma once
// Sprout's C++ library (find_package(Sprout), target Sprout::core): the grammar language, the
// derivation and the turtle, with no GL.
//
//   sprout::ParseResult r = sprout::parse("n: 5\nangle: 25.7\naxiom: F\nF -> F[+F]F[-F]F\n");
//   sprout::DeriveResult d = sprout::derive(r.grammar, r.grammar->settings.iterations);
//   std::string s = sprout::toString(*d.string, r.grammar->alphabet);
//   sprout::Geometry g;
//   sprout::interpret(*d.string, *r.grammar, {}, g);   // cylinders, leaves, polygons
#include "core/derive/derive.hpp"
#include "core/derive/draw.hpp"
#include "core/language/file_kind.hpp"
#include "core/language/grammar.hpp"
#include "core/language/module_string.hpp"
#include "core/turtle/turtle.hpp"
