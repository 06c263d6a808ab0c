#pragma once
// An L-Py string drawn by Sprout's turtle: L-Py's turtle vocabulary and defaults (PlantGL's
// turtle: heading +Z, 60 degree turns, width as a radius that `_(w)` sets, colours as
// material indices) written in Sprout's turtle vocabulary, so the picture is L-Py's turned
// into Sprout's Y-up frame (L-Py's x, y, z become Sprout's z, x, y: a rotation).
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/base/shine.hpp"
#include "core/language/diagnostic.hpp"
#include "core/language/grammar.hpp"
#include "lpy/engine/engine.hpp"

namespace sprout::lpy {

struct TurtleDefaults {
    double angle = 60;    // setAngleIncrement
    double width = 0.1;   // a radius
    int colour = 1;       // material index
    std::vector<std::uint32_t> materials;  // 0xRRGGBBAA by index; L-Py's seven by default
    std::vector<std::pair<int, Shine>> shines;  // the materials that shine (specular, emission), by index
    std::vector<std::pair<int, std::string>> textures;  // the texture materials' image files, by index, as the model names them
    std::string folder;  // the model's (placeTextures): images named relative to it are found there
};

// L-Py's default materials (PlantGL's turtle: grey, brown, green, red, yellow, blue, purple),
// each ambient x diffuse as PlantGL shows it.
std::vector<std::uint32_t> defaultMaterials();

// The drawable grammar (no rules; the axiom is the string). Modules Sprout does not draw are
// left out; `warnings` receives one line per kind of module it left out that L-Py would draw.
// `sourceOf`, when given, receives for each module of the axiom the index in `s` of the
// module it draws. `queries`: L-Py's query modules become Sprout's `?P`, whose frames the turtle reports in order
// (a walk for the frames: @g's shapes are left out, not made into triangles).
std::shared_ptr<Grammar> drawable(const LString& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                  std::vector<std::string>* warnings = nullptr, bool queries = false,
                                  std::vector<std::uint32_t>* sourceOf = nullptr);
// The same for a string of the native path (no interpretation rules ran on it).
std::shared_ptr<Grammar> drawable(const NumString& s, const ModuleClasses& classes, const TurtleDefaults& d,
                                  std::vector<std::string>* warnings = nullptr);

// The model's turtle settings and materials as its context holds them (context.cpp: openalea.lpy's
// `_state`).
TurtleDefaults turtleDefaults(const py::module_& lpyModule);
// The texture materials' images, where relative, found beside the model file (L-Py Studio runs
// a model in its folder); a warning for each that is not there (drawn in its colour).
void placeTextures(TurtleDefaults& d, const std::string& modelFile, std::vector<Diagnostic>& warnings);
// L-Py's query modules (?P ?H ...) given the turtle's state where they stand (each step,
// before the rules, when a rule reads one).
void fillQueries(Engine& engine, LString& s, const TurtleDefaults& d);

}  // namespace sprout::lpy
