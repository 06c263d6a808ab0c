// Multiscale strings (lpy/engine/match.hpp): module scales (`module I : scale = 2`, the context's
// setModuleScale) and L-Py's ways of reading a string as a tree (its option 'String matching',
// src/cpp/matching.cpp): with 'As Multiscale AxialTree' a left context is read from each
// module to its predecessor at the pattern module's scale, a right context to the next module
// at that scale (src/cpp/axialtree_manip.h predecessor_at_scale, next_module_at_scale); with
// 'As Multi-level AxialTree', at that level (the other levels skipped).
#include <climits>

#include "lpy/engine/axial_tree.hpp"
#include "lpy/engine/match.hpp"

namespace sprout::lpy {

void Matcher::readOptions() {
    if (!m_lpyModule) m_lpyModule = py::module_::import("openalea.lpy");
    py::dict state = m_lpyModule.attr("_state");  // the current context's (a model may switch it)
    const long changes = state.contains("changes") ? state["changes"].cast<long>() : 0;
    if (m_optionsOf.is(state) && changes == m_optionsChanges) return;
    m_optionsOf = state;
    m_optionsChanges = changes;
    py::object chosen = py::object(state["options"]).attr("get")("String matching");
    m_stringMatching = 1;  // 'As AxialTree', L-Py's default
    if (!chosen.is_none()) {
        if (py::isinstance<py::str>(chosen)) {
            const std::string v = chosen.cast<std::string>();
            m_stringMatching = v == "As String" ? 0 : v == "As Multi-level AxialTree" ? 2 : v == "As Multiscale AxialTree" ? 3 : 1;
        } else {
            m_stringMatching = chosen.cast<int>();
        }
    }
    const ModuleClasses& c = m_tr.classes;
    m_scale.assign(c.size(), INT_MAX);
    bool any = false;
    for (size_t k = 0; k < c.size(); ++k)
        if (c.scales[k] >= 0) m_scale[k] = c.scales[k], any = true;
    if (state.contains("scales"))
        for (auto item : py::dict(state["scales"])) {
            const int cls = c.find(item.first.cast<std::string>());
            if (cls >= 0) m_scale[size_t(cls)] = item.second.cast<int>(), any = true;
        }
    if (!any || m_stringMatching < 2) m_stringMatching = std::min(m_stringMatching, 1);
}

int Matcher::scaleOf(int cls) const { return cls >= 0 && size_t(cls) < m_scale.size() ? m_scale[size_t(cls)] : INT_MAX; }

long Matcher::predecessorAt(const LString& s, long pos, int target, int filter) {
    if (pos <= 0) return -1;
    const tree::Scale scale = [this](int cls) { return scaleOf(cls); };
    const tree::Skip skip = [this, filter](int cls) { return skipped(cls, filter); };
    return m_stringMatching == 2 ? tree::predecessorAtLevel(s, size_t(pos), target, scale, skip)
                                 : tree::predecessorAtScale(s, size_t(pos), target, scale, skip);
}

size_t Matcher::nextAt(const LString& s, size_t pos, int target, int filter) {
    constexpr size_t npos = size_t(-1);
    // L-Py's next_module_at_scale from the position after the last module matched.
    auto next = [&](size_t j) {
        while (j < s.size() && skipped(s[j].cls, filter)) ++j;
        return j;
    };
    const int previous = pos > 0 && pos - 1 < s.size() ? scaleOf(s[pos - 1].cls) : INT_MAX;
    pos = next(pos);
    if (m_stringMatching == 2) {
        while (pos < s.size() && scaleOf(s[pos].cls) != target) pos = next(pos + 1);
        return pos < s.size() ? pos : npos;
    }
    if (!(target > previous)) {  // a successor, not a component: past the components
        while (pos < s.size() && scaleOf(s[pos].cls) > target) pos = next(pos + 1);
        if (pos >= s.size()) return npos;
    }
    int current = scaleOf(s[pos].cls);
    if (current < target) {  // down into the components
        int before = current;
        do {
            pos = next(pos + 1);
            if (pos >= s.size()) return npos;
            before = current;
            current = scaleOf(s[pos].cls);
        } while (current > before && current < target);
    }
    return pos < s.size() && scaleOf(s[pos].cls) == target ? pos : npos;
}

}  // namespace sprout::lpy
