// --script FILE: viewer actions, one per line, for tests and demos.
// Index of this file:
//   [SECTION] Loading and stepping
//   [SECTION] The document
//   [SECTION] Reports
//   [SECTION] Picking
//   [SECTION] The view
//
// The commands:
//   wait                  until the newest edit is on screen
//   text <grammar>        replace the text ("\n" for line breaks)
//   set <key> <value>     a setting, as a slider would (angle, n, step, width, seed, ...)
//   define <name> <value> a define, as its slider would
//   environment <k> <value>   the k-th (from 0) environment slider, as the panel's would
//   curves                prints each of an L-Py model's 2D curves: "curve=NAME kind=K points=x,y,w;..."
//   curve-point <name> <k> <x> <y> [g]   moves point k of that curve, as a drag in its editor
//                         does; moves given the same g (a number) are one drag: one undo step
//   curve-edit <name> add|delete <k> | weight <k> <w>   a point added after point k, point k
//                         taken away, point k's weight set, as the editor's tools do (one undo
//                         step each); what refuses it is printed
//   curve-trace <png>     an image under the curve editor's curve, to trace: prints
//                         "trace=WxH" or "trace_error=why"
//   curve-preset <name> line|arc|circle|s   the curve set to that preset
//   mouse-drag-point <k> <dx> <dy> <frames>   the mouse, as ImGui sees it, presses point k of
//                         the curve open in the panel's editor, drags it (dx, dy) pixels over
//                         that many frames and lets it go (the panel scrolls to it first)
//   materials             prints an L-Py model's materials, a line each: "material=I name=N
//                         ambient=r,g,b diffuse=d specular=.. emission=.. shininess=s transparency=t"
//   material-set <i> <field> <v> [v v] | material-set <i> image <file>   sets that field of
//                         material i (a texture's: its image file) as the panel's editor
//                         does (a colour: three numbers 0..255), one undo step
//   scalars               prints an L-Py model's scalars: "scalar=NAME kind=K value=V min=A max=B"
//   scalar-add <name> Integer|Float|Bool|Category [<value> min max] | scalar-rename <name> <new> |
//   scalar-delete <name>  as the panel's scalar editor does (one undo step each)
//   colours               prints a VLab object's colour files and their first entries (RRGGBB)
//   colour-set <file> <entry> colour|ambient|diffuse|specular|emission <r g b> |
//              shininess|transparency <v> | interpolate <to>   an entry set as the Colours
//                         section sets it (0..255 colours), written in the file
//   curve-open <name> | object-open <i>   the curve editor shows that curve (an object's i-th
//                         function or contour)
//   surfaces              prints an L-Py model's NurbsPatch objects and a VLab object's Bezier
//                         patches: "surface=NAME points=x,y,z;..." (row by row)
//   surface-open <i> | surface-point <i> <u> <v> <x> <y> <z> [g]   the surface editor shows
//                         the i-th; its control point (u, v) moved there (the same g: one drag)
//   mouse-drag-surface-point <u> <v> <dx> <dy> <frames>   as mouse-drag-point, in the surface
//                         editor
//   surface-edit <i> add-row|delete-row|add-column|delete-column <k> | surface-edit <i> weight
//                         <u> <v> <w>   an L-Py patch's row or column added after k or taken
//                         away, a point's weight, as the editor's tools; "refused=why" if not
//   material-interpolate <from> <to>   the materials between made the mix of the two ends
//   object-curves         prints a VLab object's functions and contours, a line each:
//                         "object-curve=LABEL points=x,y,multiplicity;..."
//   object-point <i> <k> <x> <y> [g]   moves point k of the i-th of them (from 0), written in
//                         its file; moves given the same g are one undo step
//   object-undo | object-redo   the editor's last write to an object's files taken back, redone
//   curve-drag <name> <k> <dx> <dy> <frames>   point k dragged by (dx, dy) over that many frames,
//                         a step a frame, one gesture, no result waited for between steps
//   curve-drag-stats      once the drag's last result is on screen: prints
//                         "curve_drag_worst_frame_ms=W refined_ms=R ...": its longest frame, the
//                         time from its last step to the plant it gives, drawn whole, then the
//                         last result's parse, derive and interpret ms, the still picture's ms,
//                         when the result came (result_after_ms), plants_during_drag and the
//                         drag's own time (drag_ms: its first step to its last)
//   undo | redo           as Ctrl+Z / Ctrl+Shift+Z in the grammar editor
//   show-environment on|off | light-slice <height>|off   the environment's drawing
//   pick <x> <y>          a click at window pixel (x, y): prints
//                         "module=NAME index=I step=S rule_line=L" (with " rule_label=p2" for
//                         a rule labelled in ABOP's notation; "module=none" for nothing)
//   highlight-rule <line> every stem and leaf the rule on that line made: prints "highlighted=N"
//   inspect <step> <module>   the derivation inspector on that step, that module chosen; prints
//                         what it says of the module, a line each ("inspect: ...")
//   view-draws            prints "view_draws=N sketched=M full_moving=F": how many times the 3D
//                         view has been drawn, how many of those were a big scene's sketch
//                         (moving) and how many moving frames were at full quality (a scene
//                         whose still picture takes a few ms: a GPU, a small plant), then
//                         "staged_uploads=U mapped_uploads=0|1": how many plants went to the
//                         GPU a piece per frame, and whether into persistently mapped buffers
//   status                prints "status=TEXT": the message the window's status line shows
//   gl-info               prints "gl_renderer=R" and "gl_version=V", a line each: the context's
//                         GL_RENDERER and GL_VERSION (which GPU, or Mesa's llvmpipe, drew)
//   wait-thumbnails       until the presets' thumbnails are made (benchmarks)
//   frame-stats           prints "moving_worst_ms=A moving_mean_ms=B refine_ms=T
//                         refine_worst_frame_ms=W peak_mb=M refine_frames=F refine_drawing_ms=D
//                         moving_differ_pct=P": the longest and mean frame that moved the view
//                         since the last frame-stats, the time the last still view took to
//                         draw whole (a piece a frame), its longest frame, the process's peak
//                         memory, the frames the still view took and the time its pieces drew,
//                         and the share of pixels (%) that differ by more than 30 of 765 between
//                         the last moving picture as shown and the still view after it (-1:
//                         none measured), and what the longest moving frame drew (its view's
//                         size and time, and whether it drew the shadow map, the sketch, or
//                         took a new plant), the frames that copied and drew the panel, and
//                         whether the ground's shadow texture for moving frames is made from
//                         the last shadow map
//   drag <dx> <dy> <frames>   orbits as a left-button drag of dx, dy pixels over that many
//                         frames, the button still held after it; release   lets it go
//   step <k> | play | pause | frame | yaw <deg> | pitch <deg> | zoom <factor> | sleep <seconds>
//   moving full|auto      the View section's "full quality moving" on or off
//   screenshot <path> [WxH]
//   export <path>         as File > Export model (waits until the file is written)
//   record growth|turntable <path>   as Record video (waits until it is written)
//   saveas <path>         save the text (as File > Save as)
//   recover               take the autosaved text of a session that did not end normally
//   crash                 the process is killed on the spot (tests of crash recovery)
//   quit
#include "app/render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "app/args.hpp"
#include "app/viewer/window/app.hpp"
#include "app/plant/text_edit.hpp"
#include "app/viewer/window/panel_sections.hpp"
#include "core/base/bounded.hpp"
#include "core/base/read_file.hpp"

namespace sprout::viewer {

// [SECTION] Loading and stepping
bool Script::load(const std::string& path, std::string& error) {
    std::optional<std::string> text = readFile(path);
    if (!text) {
        error = "cannot open the script";
        return false;
    }
    std::istringstream in(*text);
    std::string line;
    while (std::getline(in, line))
        if (!line.empty() && line[0] != '#') m_lines.push_back(line);
    if (m_lines.empty()) m_lines.push_back("quit");
    return true;
}

bool Script::resultIn(const App& app) const { return app.state.latest() && app.state.latest()->generation >= m_waitFor; }

bool Script::waitsForWorker(const App& app) const {
    if (m_curve.frames > 0 || m_mouse.frames >= 0 || m_dragFrames > 0 || m_lines.empty()) return false;
    return app.state.worker().busy() && !resultIn(app);
}

bool Script::step(App& app) {
    if (m_curve.frames > 0) {  // a curve's point dragged: a step a frame, no result waited for
        const double now = glfwGetTime();
        if (m_curve.lastFrame > 0) m_curve.worstMs = std::max(m_curve.worstMs, (now - m_curve.lastFrame) * 1000);
        if (const auto p = app.state.plant(); p && p->generation != m_curve.lastGeneration) {  // a new plant on screen
            if (m_curve.lastFrame > 0) ++m_curve.shown;
            m_curve.lastGeneration = p->generation;
        }
        if (m_curve.lastFrame == 0) m_curve.startedAt = now;
        m_curve.lastFrame = now;
        detail::nudgeCurvePoint(app, m_curve.name, m_curve.point, m_curve.dx, m_curve.dy, m_curve.gesture);
        if (--m_curve.frames == 0) m_curve.endedAt = now;
        app.scriptShaping = m_curve.frames > 0;
        m_waitFor = app.state.generation();  // what comes next waits for the last step's result
        return true;
    }
    if (m_mouse.frames >= 0) return mouseStep(app);
    if (m_dragFrames > 0) {  // a drag in progress: one move a frame, as the mouse makes them
        app.camera.yaw -= m_dragYaw;
        app.camera.pitch = std::clamp(app.camera.pitch + m_dragPitch, -89.0f, 89.0f);
        app.needsRedraw = true;
        --m_dragFrames;
        return true;
    }
    while (!m_lines.empty()) {
        std::istringstream in(m_lines.front());
        std::string cmd;
        in >> cmd;
        // Every action waits until the result of the script's last edit is on screen (an
        // animation may post newer requests meanwhile; those are not waited for).
        if (m_curve.endedAt > 0 && m_curve.resultAt == 0 && resultIn(app))
            m_curve.resultAt = glfwGetTime();  // the drag's last result, from the worker
        if (!resultIn(app)) return true;
        if (glfwGetTime() < m_sleepUntil) return true;
        if (!app.viewSettled()) return true;  // and until the view shows it whole, with its environment
        if (app.exportJob.running()) return true;
        if (app.videoJob.running()) {
            if (std::string m = app.videoJob.poll(); !m.empty()) app.say(m);
            return true;
        }
        m_lines.pop_front();
        struct After {
            Script& s;
            App& a;
            ~After() { s.m_waitFor = a.state.generation(); }
        } after{*this, app};
        if (auto done = documentCommand(app, cmd, in)) return *done;
        if (auto done = curveCommand(app, cmd, in)) return *done;
        if (auto done = objectCommand(app, cmd, in)) return *done;
        if (auto done = reportCommand(app, cmd, in)) return *done;
        if (auto done = pickCommand(app, cmd, in)) return *done;
        return viewCommand(app, cmd, in);
    }
    return false;
}

// [SECTION] The document
// The document: waiting, the text and its values, trust, saving, the process itself.
std::optional<bool> Script::documentCommand(App& app, const std::string& cmd, std::istringstream& in) {
    if (cmd == "wait") return true;  // one frame drawn after the result
    if (cmd == "sleep") {  // wall-clock time, for animations
        double seconds = 0;
        in >> seconds;
        m_sleepUntil = glfwGetTime() + seconds;
        return true;
    }
    if (cmd == "quit") return false;
    if (cmd == "crash") std::raise(SIGKILL);
    if (cmd == "recover") {
        app.state.restoreRecovered();
        return true;
    }
    if (cmd == "trust") {  // as the trust bar's buttons: yes, no; "trust ?" prints the state
        std::string v;
        in >> v;
        if (v == "yes" || v == "no") app.state.answerTrust(v == "yes");
        std::printf("python=%s\n", app.state.pythonQuestion() ? "asking" : app.state.pythonBlocked() ? "refused" : "allowed");
        std::fflush(stdout);
        return true;
    }
    if (cmd == "diagnostics") {  // the messages of the result shown: "diagnostic=LINE:COL: message"
        if (auto latest = app.state.latest()) {
            for (const auto& d : latest->diagnostics) std::printf("diagnostic=%d:%d: %s\n", d.line, d.col, d.message.c_str());
            if (!latest->message.empty()) std::printf("message=%s\n", latest->message.c_str());
        }
        std::printf("plant=%s\n", app.state.plant() ? "shown" : "none");
        std::fflush(stdout);
        return true;
    }
    if (cmd == "saveas") {
        std::string path, error;
        in >> path;
        app.say(app.state.saveAs(path, error) ? "saved " + path : error);
        return true;
    }
    if (cmd == "text") {
        std::string rest;
        std::getline(in, rest);
        std::string text;
        for (size_t i = rest.find_first_not_of(' '); i < rest.size(); ++i) {
            if (rest[i] == '\\' && i + 1 < rest.size() && rest[i + 1] == 'n') {
                text += '\n';
                ++i;
            } else {
                text += rest[i];
            }
        }
        app.state.setText(text);
        return true;
    }
    if (cmd == "set") {
        std::string key;
        double v = 0;
        in >> key >> v;
        if (key == "n") app.state.setIterations(saturate<int>(v));
        else app.state.setDirectiveValue(key, v);
        return true;
    }
    if (cmd == "define") {
        std::string name;
        double v = 0;
        in >> name >> v;
        app.state.setDefineValue(name, v);
        return true;
    }
    if (cmd == "environment") {
        size_t k = 0;
        double v = 0;
        in >> k >> v;
        auto numbers = environmentNumbers(app.state.text());
        if (k < numbers.size()) app.state.setText(setEnvironmentNumber(app.state.text(), numbers[k], v));
        else std::fprintf(stderr, "script: there is no environment slider %zu\n", k);
        return true;
    }
    return std::nullopt;
}

// [SECTION] Reports

// The mouse held and let go, and what the window measured.
std::optional<bool> Script::reportCommand(App& app, const std::string& cmd, std::istringstream& in) {
    if (cmd == "drag") {
        float dx = 0, dy = 0;
        int frames = 1;
        in >> dx >> dy >> frames;
        frames = std::max(1, frames);
        app.scriptDragging = true;  // held: the view moves at interactive quality
        m_dragFrames = frames;
        m_dragYaw = dx * 0.4f / float(frames);  // as the mouse: 0.4 degrees a pixel
        m_dragPitch = dy * 0.4f / float(frames);
        return true;
    }
    if (cmd == "release") {
        app.scriptDragging = false;
        app.needsRedraw = true;
        return true;
    }
    if (cmd == "wait-thumbnails") {  // until the presets' thumbnails are made
        if (app.thumbnails.making() || !m_thumbnailsSeen) {
            m_thumbnailsSeen = true;  // a frame's poll has run since: one is started if any is missing
            m_lines.push_front(in.str());
        }
        return true;
    }
    if (cmd == "frame-stats") {
        long peakKb = 0;  // the process's peak resident memory
        if (std::FILE* f = std::fopen("/proc/self/status", "r")) {
            char line[256];
            while (std::fgets(line, sizeof line, f))
                if (std::sscanf(line, "VmHWM: %ld kB", &peakKb) == 1) break;
            std::fclose(f);
        }
        std::printf("moving_worst_ms=%.1f moving_mean_ms=%.1f refine_ms=%.1f refine_worst_frame_ms=%.1f peak_mb=%.0f refine_frames=%d refine_drawing_ms=%.1f moving_differ_pct=%.2f moving_worst_was=%s panel_copied_frames=%llu panel_drawn_frames=%llu ground_shadow_current=%d\n",
                    app.movingWorstMs, app.movingFrames ? app.movingTotalMs / double(app.movingFrames) : 0.0, app.drawMs,
                    app.refineWorstMs, double(peakKb) / 1024, app.refineFrames, app.renderer.lastPictureMs(), app.movingDifferPct,
                    app.movingWorstWhat.empty() ? "none" : app.movingWorstWhat.c_str(),
                    static_cast<unsigned long long>(app.panelCopies), static_cast<unsigned long long>(app.panelDraws),
                    int(app.renderer.groundShadowCurrent()));
        std::fflush(stdout);
        app.movingWorstMs = app.movingTotalMs = 0;
        app.movingWorstWhat.clear();
        app.movingFrames = 0;
        return true;
    }
    if (cmd == "gl-info") {
        std::printf("gl_renderer=%s\ngl_version=%s\n", app.renderer.glRenderer().c_str(), app.renderer.glVersion().c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "status") {
        std::printf("status=%s\n", app.status.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "view-draws") {
        std::printf("view_draws=%llu sketched=%llu full_moving=%llu staged_uploads=%llu mapped_uploads=%d\n",
                    static_cast<unsigned long long>(app.viewDraws), static_cast<unsigned long long>(app.sketchDraws),
                    static_cast<unsigned long long>(app.fullMovingDraws), static_cast<unsigned long long>(app.stagedUploads),
                    app.renderer.persistentUploads() ? 1 : 0);
        std::fflush(stdout);
        return true;
    }
    return std::nullopt;
}

// [SECTION] Picking

// Picking and the inspector.
std::optional<bool> Script::pickCommand(App& app, const std::string& cmd, std::istringstream& in) {
    // Picking and the inspector need the derivation's origins: the first time, ask for
    // them and come back once the plant that has them is on screen. A plant that cannot
    // get them (the text has errors since) is answered without.
    auto needsOrigins = [&](bool forestWillDo) {
        auto plant = app.state.plant();
        if (!plant || plant->pick || (forestWillDo && plant->forest)) return false;
        if (app.state.picking() && !app.state.worker().busy()) return false;  // asked, and none came
        app.state.setPicking(true);
        m_lines.push_front(in.str());
        return true;
    };
    if (cmd == "inspect") {
        if (needsOrigins(false)) return true;
        if (!app.state.plant() || !app.state.plant()->pick) {
            std::fprintf(stderr, "script: inspect: the plant on screen has no derivation to inspect\n");
            return true;
        }
        std::int64_t module = 0;
        in >> app.inspector.step >> module;
        app.inspector.chosen = module;
        app.inspector.first = std::uint64_t(std::max<std::int64_t>(0, module - 4));
        app.openInspector = true;
        for (const std::string& line : describeModule(app.state.plant()->pick->record, app.inspector.step, std::uint32_t(module)))
            std::printf("inspect: %s\n", line.c_str());
        std::fflush(stdout);
        return true;
    }
    if (cmd == "pick" || cmd == "highlight-rule") {
        auto plant = app.state.plant();
        if (!plant || !plant->geometry) {
            std::printf(cmd == "pick" ? "module=none\n" : "highlighted=0\n");
            std::fflush(stdout);
            return true;
        }
        if (needsOrigins(cmd == "pick")) return true;
        if (cmd == "pick") {
            double x = 0, y = 0;
            in >> x >> y;
            app.pickAt(x, y);
            std::printf("%s\n", app.describeSelection().c_str());
        } else {
            int line = 0;
            in >> line;
            app.setHighlightLine(line);
            app.updateHighlight();
            std::printf("highlighted=%zu\n", app.highlightCount);
        }
        std::fflush(stdout);
        return true;
    }
    return std::nullopt;
}

// [SECTION] The view

// The view, growth, and what the window writes: pictures, videos, models. Any other line
// is passed over.
bool Script::viewCommand(App& app, const std::string& cmd, std::istringstream& in) {
    if (cmd == "show-environment" || cmd == "light-slice") {
        std::string v;
        in >> v;
        if (cmd == "show-environment") app.view.showEnvironment = v != "off";
        else if (v == "off") app.view.lightSlice = false;
        else {
            const float h = std::strtof(v.c_str(), nullptr);  // 0 to 1; NaN is 0
            app.view.lightSlice = true, app.view.sliceHeight = h >= 0 && h <= 1 ? h : h > 1 ? 1.0f : 0.0f;
        }
        app.environmentDirty = true;
        return true;
    }
    if (cmd == "step") {
        int k = 0;
        in >> k;
        app.state.setDisplayStep(k);
        return true;
    }
    if (cmd == "play") app.state.setPlaying(true);
    else if (cmd == "pause") app.state.setPlaying(false);
    else if (cmd == "frame") app.frame();
    else if (cmd == "moving") {
        std::string how;
        in >> how;
        if (how != "full" && how != "auto") std::fprintf(stderr, "script: moving: full or auto, not '%s'\n", how.c_str());
        else app.view.fullWhileMoving = how == "full";
    } else if (cmd == "yaw" || cmd == "pitch") {
        float v = 0;
        in >> v;
        (cmd == "yaw" ? app.camera.yaw : app.camera.pitch) = v;
        app.needsRedraw = true;
    } else if (cmd == "zoom") {  // as the mouse wheel: closer by this factor
        float f = 1;
        in >> f;
        if (f > 0) app.camera.zoom(1 / f);
        app.needsRedraw = true;
    } else if (cmd == "screenshot") {
        std::string path, size;
        in >> path >> size;
        int w = 0, h = 0;  // 0: the window's size
        if (!size.empty() && !parseSize(size, w, h))
            app.say("screenshot: the size must be WIDTHxHEIGHT between 16x16 and 8192x8192");
        else
            app.takeScreenshot(path, w, h);
    } else if (cmd == "record") {
        std::string kind, path;
        in >> kind >> path;
        app.recordVideo(kind, path);
    } else if (cmd == "export") {
        std::string path;
        in >> path;
        app.exportModel(path);
    }
    return true;
}

}  // namespace sprout::viewer
