// The script's commands on curves and a VLab object's files (app/viewer/window/script.cpp lists
// every command): moving, adding, deleting and weighting points as the panel's curve editor
// does, the mouse dragging one, and the undo of either.
#include "app/render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "app/plant/lpy_materials.hpp"
#include "app/plant/lpy_objects.hpp"
#include "app/plant/lsys_curves.hpp"
#include "app/plant/lpy_scalars.hpp"
#include "app/viewer/window/app.hpp"
#include "app/viewer/window/curve_canvas.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "app/viewer/window/surface_canvas.hpp"

namespace sprout::viewer {

// `mouse-drag-point`, a frame at a time: three frames for the panel to scroll to the editor,
// the mouse over the point, pressed, moved `steps` times, let go, then given back.
bool Script::mouseStep(App& app) {
    auto& m = app.scriptMouse;
    const int f = m_mouse.frames++, steps = m_mouse.steps;
    if (f < 3) return true;
    if (f == 3) {
        const auto at = m_mouse.surface ? detail::surfacePointOnScreen(m_mouse.u, m_mouse.v) : detail::curvePointOnScreen(m_mouse.point);
        if (!at) {
            std::fprintf(stderr, "script: no point %zu in the curve editor\n", m_mouse.point);
            m_mouse.frames = -1;
            return true;
        }
        m_mouse.x = (*at)[0], m_mouse.y = (*at)[1];
        m = {true, false, m_mouse.x, m_mouse.y};
    } else if (f == 4) {
        m.down = true;
    } else if (f < 5 + steps) {
        const float t = float(f - 4) / float(steps);
        m.x = m_mouse.x + t * m_mouse.dx, m.y = m_mouse.y + t * m_mouse.dy;
    } else if (f == 5 + steps) {
        m.down = false;
    } else {
        m.on = false;
        m_mouse.frames = -1;
        m_waitFor = app.state.generation();  // what comes next waits for the drag's result
    }
    return true;
}

std::optional<bool> Script::curveCommand(App& app, const std::string& cmd, std::istringstream& in) {
    if (cmd == "curve-point") {
        std::string name;
        size_t k = 0;
        double x = 0, y = 0;
        std::uint64_t g = 0;
        in >> name >> k >> x >> y;
        if (!(in >> g)) g = 0;
        if (!detail::moveCurvePoint(app, name, k, x, y, g ? (std::uint64_t(1) << 62) + g : 0)) std::fprintf(stderr, "script: no point %zu of a curve %s\n", k, name.c_str());
        return true;
    }
    if (cmd == "mouse-drag-point" || cmd == "mouse-drag-surface-point") {
        m_mouse = MouseDrag{};
        m_mouse.surface = cmd == "mouse-drag-surface-point";
        if (m_mouse.surface) in >> m_mouse.u >> m_mouse.v;
        else in >> m_mouse.point;
        in >> m_mouse.dx >> m_mouse.dy >> m_mouse.steps;
        m_mouse.steps = std::max(1, m_mouse.steps);
        m_mouse.frames = 0;
        if (m_mouse.surface) detail::surfacePointOnScreen(m_mouse.u, m_mouse.v);  // scrolls the panel to the editor
        else detail::curvePointOnScreen(m_mouse.point);
        return true;
    }
    if (cmd == "surfaces") {
        for (const std::string& l : detail::surfaceLines(app)) std::printf("%s\n", l.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "surface-open") {
        size_t i = 0;
        in >> i;
        detail::openSurface(i);
        return true;
    }
    if (cmd == "surface-point") {  // I U V X Y Z [G]
        size_t i = 0, u = 0, v = 0;
        std::array<double, 3> p{};
        std::uint64_t g = 0;
        in >> i >> u >> v >> p[0] >> p[1] >> p[2];
        if (!(in >> g)) g = 0;
        if (!detail::setSurfacePoint(app, i, u, v, p, g ? (std::uint64_t(1) << 62) + g : 0))
            std::fprintf(stderr, "script: no point %zu,%zu of surface %zu\n", u, v, i);
        m_waitFor = app.state.generation();
        return true;
    }
    if (cmd == "surface-edit") {  // I add-row|delete-row|add-column|delete-column K | I weight U V W
        size_t i = 0, k = 0, v = 0;
        std::string what;
        double w = 0;
        in >> i >> what >> k;
        if (what == "weight") in >> v >> w;
        const std::string why = detail::editSurface(app, i, what, k, w, v);
        if (!why.empty()) std::printf("refused=%s\n", why.c_str()), std::fflush(stdout);
        m_waitFor = app.state.generation();
        return true;
    }
    if (cmd == "curve-trace") {  // an image under the curve editor's curve
        std::string path;
        std::getline(in >> std::ws, path);
        const std::string why = detail::loadTraceImage(path);
        if (why.empty()) std::printf("trace=%dx%d\n", detail::traceImageSize()[0], detail::traceImageSize()[1]);
        else std::printf("trace_error=%s\n", why.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "curve-edit" || cmd == "curve-preset") {
        std::string name, op;
        double a = 0, b = 0;
        in >> name >> op >> a >> b;
        const std::string why = cmd == "curve-edit" ? detail::editCurve(app, name, op, a, b) : detail::presetCurve(app, name, op);
        if (!why.empty()) std::fprintf(stderr, "script: %s\n", why.c_str());
        return true;
    }
    if (cmd == "curve-drag") {
        int frames = 1;
        in >> m_curve.name >> m_curve.point >> m_curve.dx >> m_curve.dy >> frames;
        m_curve.frames = std::max(1, frames);
        m_curve.dx /= m_curve.frames;
        m_curve.dy /= m_curve.frames;
        m_curve.gesture = detail::newGesture();
        // The camera drag's measure (the moving picture read back and compared with the
        // still one) is not this drag's: its read-back took 25 ms of the refined time.
        app.measureMoving = false;
        m_curve.lastFrame = m_curve.worstMs = m_curve.resultAt = 0;
        m_curve.shown = 0;
        return true;
    }
    if (cmd == "curve-drag-stats") {  // run once the drag's last result is on screen
        const auto shown = app.state.plant();  // and where the last result's time went, on the worker
        std::printf("curve_drag_worst_frame_ms=%.1f refined_ms=%.1f parse_ms=%.1f derive_ms=%.1f interpret_ms=%.1f picture_ms=%.1f "
                    "result_after_ms=%.1f plants_during_drag=%d drag_ms=%.0f\n",
                    m_curve.worstMs, (glfwGetTime() - m_curve.endedAt) * 1000, shown ? shown->parseMs : 0.0, shown ? shown->deriveMs : 0.0,
                    shown ? shown->interpretMs : 0.0, app.renderer.lastPictureMs(), (m_curve.resultAt - m_curve.endedAt) * 1000, m_curve.shown,
                    (m_curve.endedAt - m_curve.startedAt) * 1000);
        std::fflush(stdout);
        return true;
    }
    if (cmd == "undo" || cmd == "redo") {
        if (cmd == "undo" ? app.editor.model().undo() : app.editor.model().redo()) app.state.setText(app.editor.text());
        return true;
    }
    if (cmd == "curves") {
        const std::vector<LpyCurve> all = lpyCurves(app.state.text());
        for (size_t k = 0; k < all.size(); ++k) {  // each version by its key (NAME#k: an earlier one)
            const LpyCurve& c = all[k];
            std::printf("curve=%s kind=%d points=", lpyCurveKey(all, k).c_str(), int(c.kind));
            for (size_t i = 0; i < c.points.size(); ++i) std::printf("%s%.9g,%.9g,%.9g", i ? ";" : "", c.points[i][0], c.points[i][1], c.points[i][2]);
            std::printf("\n");
        }
        for (const LsysCurve& c : lsysCurves(app.state.text())) {
            std::printf("curve=%s kind=%s points=", c.name.c_str(), c.function ? "function" : "contour");
            for (size_t i = 0; i < c.points.size(); ++i) std::printf("%s%.9g,%.9g", i ? ";" : "", c.points[i][0], c.points[i][1]);
            std::printf("\n");
        }
        std::fflush(stdout);
        return true;
    }
    return std::nullopt;
}

// A model's other objects: a VLab object's functions, contours and colour files, surfaces,
// an L-Py model's materials and scalars.
std::optional<bool> Script::objectCommand(App& app, const std::string& cmd, std::istringstream& in) {
    if (cmd == "object-curves") {
        for (const std::string& l : detail::objectCurves(app)) std::printf("%s\n", l.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "object-point") {
        size_t i = 0, k = 0;
        double x = 0, y = 0;
        std::uint64_t g = 0;
        in >> i >> k >> x >> y;
        if (!(in >> g)) g = 0;
        if (!detail::moveObjectPoint(app, i, k, x, y, g ? (std::uint64_t(1) << 62) + g : 0))
            std::fprintf(stderr, "script: no point %zu of object curve %zu\n", k, i);
        m_waitFor = app.state.generation();
        return true;
    }
    if (cmd == "object-undo" || cmd == "object-redo") {
        if (!detail::objectUndo(app, cmd == "object-redo")) std::fprintf(stderr, "script: nothing to %s\n", cmd.c_str() + 7);
        m_waitFor = app.state.generation();
        return true;
    }
    if (cmd == "materials") {
        for (const std::string& l : detail::materialLines(app)) std::printf("%s\n", l.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "material-interpolate") {  // FROM TO: one undo step
        int from = 0, to = 0;
        in >> from >> to;
        std::string error;
        const std::string text = interpolateLpyMaterials(app.state.text(), from, to, error);
        if (text.empty()) std::fprintf(stderr, "script: %s\n", error.c_str());
        else app.state.setText(text, detail::newGesture());
        return true;
    }
    if (cmd == "material-set") {  // INDEX FIELD V [V V] | INDEX image FILE: one undo step
        int index = 0;
        std::string field;
        in >> index >> field;
        if (field == "image") {
            std::string file;
            std::getline(in >> std::ws, file);
            field += " " + file;
        }
        std::vector<double> values;
        for (double v; in >> v;) values.push_back(v);
        const std::string why = detail::setMaterialField(app, index, field, values);
        if (!why.empty()) std::fprintf(stderr, "script: %s\n", why.c_str());
        return true;
    }
    if (cmd == "scalar-add" || cmd == "scalar-rename" || cmd == "scalar-delete") {
        // scalar-add NAME Integer|Float|Bool|Category VALUE [MIN MAX]; scalar-rename NAME NEW; scalar-delete NAME
        std::string name, arg, error, text;
        in >> name >> arg;
        if (cmd == "scalar-add") {
            LpyScalar s;
            s.name = name;
            s.kind = arg == "Integer"    ? LpyScalar::Kind::Integer
                     : arg == "Bool"     ? LpyScalar::Kind::Bool
                     : arg == "Category" ? LpyScalar::Kind::Category
                                         : LpyScalar::Kind::Float;
            in >> s.value >> s.min >> s.max;
            text = addLpyScalar(app.state.text(), s, error);
        } else {
            text = cmd == "scalar-rename" ? renameLpyScalar(app.state.text(), name, arg, error) : removeLpyScalar(app.state.text(), name, error);
        }
        if (text.empty()) std::fprintf(stderr, "script: %s\n", error.c_str());
        else app.state.setText(text, detail::newGesture());
        return true;
    }
    if (cmd == "curve-open" || cmd == "object-open") {  // the editor shows that curve (an object's: by its number)
        std::string name;
        in >> name;
        detail::openCurve(app, cmd == "object-open" ? "object:" + name : name);
        return true;
    }
    if (cmd == "colours") {
        for (const std::string& l : detail::colourLines(app)) std::printf("%s\n", l.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "colour-set") {  // FILE ENTRY FIELD V...: a map's "colour r g b" or "interpolate TO"; a material's field
        size_t file = 0;
        int entry = 0;
        std::string field;
        in >> file >> entry >> field;
        std::vector<double> values;
        for (double x; in >> x;) values.push_back(x);
        const std::string why = detail::setColourEntry(app, file, entry, field, values);
        if (!why.empty()) std::fprintf(stderr, "script: %s\n", why.c_str());
        m_waitFor = app.state.generation();
        return true;
    }
    if (cmd == "scalars") {
        for (const LpyScalar& s : lpyScalars(app.state.text()))
            std::printf("scalar=%s kind=%d value=%g min=%g max=%g\n", s.name.c_str(), int(s.kind), s.value, s.min, s.max);
        std::fflush(stdout);
        return true;
    }
    return std::nullopt;
}

}  // namespace sprout::viewer
