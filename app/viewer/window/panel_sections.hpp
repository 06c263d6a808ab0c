#pragma once
// Private to app/viewer: the ImGui panel's sections (panel_grammar.cpp, panel_sections.cpp)
// and colours, which drawPanel (panel.cpp) puts together.
#include <imgui.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "app/viewer/window/app.hpp"

namespace sprout::viewer::detail {

inline const ImVec4 kError(1.0f, 0.45f, 0.4f, 1), kWarning(1.0f, 0.8f, 0.35f, 1), kDim(0.65f, 0.65f, 0.65f, 1);

// panel_grammar.cpp: the grammar's editor and its messages; which rule made a picked branch.
void grammarSection(App& app);
void whySection(App& app);
// panel_sections.cpp: a VLab object, parameters (or an IFS's maps), growth, the environment, view and light,
// presets.
void parameterSection(App& app);
void vlabSection(App& app, const VlabSummary& object);  // a VLab object's description, files, notes
void growthSection(App& app);
void environmentSection(App& app, const Environment& env);
void viewSection(App& app);
void presetSection(App& app);
// panel_curves.cpp: an L-Py model's 2D curves, each in an editor whose points the mouse drags;
// moveCurvePoint is what a drag does (the script's curve-point too): false for no such point.
bool hasLpyCurves(App& app);
// A .lsys grammar's own functions and contours (`function:`, `contour:`), in the same editor.
bool hasLsysCurves(App& app);
void lsysCurveSection(App& app);
// Opens that curve in the editor ("object:I": a VLab object's I-th function or contour).
void openCurve(App& app, const std::string& name);
void curveSection(App& app);
bool moveCurvePoint(App& app, const std::string& name, size_t k, double x, double y, std::uint64_t gesture = 0);
// A VLab object's functions and contours (the files its view file names), in the same editor,
// written back in VLab's formats; objectCurves lists them ("object-curve=LABEL points=x,y,m;..."),
// moveObjectPoint moves point k of the which-th, objectUndo takes the last write back (or redoes).
bool hasVlabCurves(App& app);
void vlabCurveSection(App& app);
std::vector<std::string> objectCurves(App& app);
bool moveObjectPoint(App& app, size_t which, size_t k, double x, double y, std::uint64_t gesture = 0);
bool objectUndo(App& app, bool redo);
// Writes a file of the object (atomically; one undo step a gesture with the others) and
// derives the object again.
bool writeObjectFile(App& app, const std::string& path, const std::string& bytes, std::uint64_t gesture);
// The version of the object's files the editors wrote (another after each write or undo).
std::uint64_t objectFilesVersion();
// panel_surfaces.cpp: an L-Py model's NurbsPatch objects and a VLab object's Bezier patches in
// the 3D surface editor; surfaceLines lists them ("surface=NAME points=x,y,z;..." [u][v] row by
// row), setSurfacePoint moves control point (u, v) of the which-th, openSurface opens it.
bool hasSurfaces(App& app);
void surfaceSection(App& app);
std::vector<std::string> surfaceLines(App& app);
bool setSurfacePoint(App& app, size_t which, size_t u, size_t v, const std::array<double, 3>& p, std::uint64_t gesture = 0);
void openSurface(size_t which);
// An L-Py patch's tools: `what` add-row|delete-row|add-column|delete-column after or at row or
// column k, or weight (point (k, v) weighing `weight`), one undo step; "" or why not.
std::string editSurface(App& app, size_t which, const std::string& what, size_t k, double weight = 0, size_t v = 0);
// panel_colours.cpp: a VLab object's material sets and colour maps, each entry edited as medit
// and palette edit them; colourLines lists them for the script (`colours`), setColourEntry sets
// one ("" when done, else what stopped it): a map's entry "r g b" (0..255), a material's field.
bool hasVlabColours(App& app);
void vlabColourSection(App& app);
std::vector<std::string> colourLines(App& app);
std::string setColourEntry(App& app, size_t file, int entry, const std::string& field, const std::vector<double>& values);
// panel_materials.cpp: an L-Py model's materials, each edited with colour editors and sliders;
// materialLines lists them as the script's `materials` prints them, setMaterialField sets one
// field of one ("" when done, else what stopped it).
bool hasLpyMaterials(App& app);
void materialSection(App& app);
std::vector<std::string> materialLines(App& app);
std::string setMaterialField(App& app, int index, const std::string& field, const std::vector<double>& values, std::uint64_t gesture = 0);
// A new gesture's id: the changes a drag in the panel makes carry it, and undo takes them back
// together (ViewerState::setText).
std::uint64_t newGesture();
// The point moved by (dx, dy) from where it is (a scripted drag's step).
bool nudgeCurvePoint(App& app, const std::string& name, size_t k, double dx, double dy, std::uint64_t gesture);
// The editor's other changes, one undo step each (the script's curve-edit and curve-preset):
// op "add" (a point after point a), "delete" (point a), "weight" (point a's weight to b);
// presets line, arc, circle, s. "" when done, else what stopped it.
std::string editCurve(App& app, const std::string& name, const std::string& op, double a, double b = 0);
std::string presetCurve(App& app, const std::string& name, const std::string& preset);

}  // namespace sprout::viewer::detail
