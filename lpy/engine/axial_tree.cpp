// L-Py's axial tree navigation (lpy/engine/axial_tree.hpp), written from src/cpp/axialtree_manip.h.
#include "lpy/engine/axial_tree.hpp"
#include "lpy/translate/translate.hpp"

#include <climits>
#include <deque>

namespace sprout::lpy::tree {
namespace {

long closing(const LString& s, size_t open) {  // the ']' of the '[' at `open`, or -1
    int depth = 0;
    for (size_t j = open; j < s.size(); ++j) {
        if (isPush(s[j])) ++depth;
        else if (isPop(s[j]) && --depth == 0) return long(j);
    }
    return -1;
}

long opening(const LString& s, size_t close) {  // the '[' of the ']' at `close`, or -1
    int depth = 0;
    for (long j = long(close); j >= 0; --j) {
        if (isPop(s[size_t(j)])) ++depth;
        else if (isPush(s[size_t(j)]) && --depth == 0) return j;
    }
    return -1;
}

// The first module of the branches that open at j (and of branches opened at their start).
void branchHeads(const LString& s, size_t j, std::vector<long>& out) {
    while (j < s.size() && isPush(s[j])) {
        const long c = closing(s, j);
        size_t k = j + 1;
        if (k < s.size() && isPush(s[k])) branchHeads(s, k, out);
        while (k < s.size() && isPush(s[k])) {
            const long ck = closing(s, k);
            if (ck < 0) return;
            k = size_t(ck) + 1;
        }
        if (k < s.size() && !isPop(s[k])) out.push_back(long(k));
        if (c < 0) return;
        j = size_t(c) + 1;
    }
}

int scaleAt(const LString& s, long i, const Scale& scaleOf) { return i < 0 ? 0 : scaleOf(s[size_t(i)].cls); }

}  // namespace

bool isPush(const LModule& m) { return m.cls == ModuleClasses::kPush; }
bool isPop(const LModule& m) { return m.cls == ModuleClasses::kPop; }

long parentOf(const LString& s, size_t i, const Skip& skip) {
    for (long j = long(i) - 1; j >= 0; --j) {
        if (isPop(s[size_t(j)])) {
            j = opening(s, size_t(j));
            if (j < 0) return -1;
        } else if (!isPush(s[size_t(j)]) && !(skip && skip(s[size_t(j)].cls))) {
            return j;
        }
    }
    return -1;
}

long directSonOf(const LString& s, size_t i) {
    for (size_t j = i + 1; j < s.size(); ++j) {
        if (isPop(s[j])) return -1;
        if (!isPush(s[j])) return long(j);
        const long c = closing(s, j);
        if (c < 0) return -1;
        j = size_t(c);
    }
    return -1;
}

std::vector<long> lateralSonsOf(const LString& s, size_t i) {
    std::vector<long> out;
    branchHeads(s, i + 1, out);
    return out;
}

std::vector<long> childrenOf(const LString& s, size_t i) {
    std::vector<long> out = lateralSonsOf(s, i);
    if (long d = directSonOf(s, i); d >= 0) out.push_back(d);
    return out;
}

long complexOf(const LString& s, size_t i, int scale, const Scale& scaleOf) {
    if (i == 0 || !(scaleOf(s[i].cls) < scale)) return -1;
    long p = parentOf(s, i);
    while (p >= 0 && scaleAt(s, p, scaleOf) < scale) p = parentOf(s, size_t(p));
    return p >= 0 && scaleAt(s, p, scaleOf) == scale ? p : -1;
}

std::vector<long> componentsOf(const LString& s, size_t i, const Scale& scaleOf, const int* scale) {
    std::vector<long> out;
    if (i >= s.size() || isPop(s[i])) return out;
    const int current = scaleOf(s[i].cls);
    std::deque<long> todo;
    for (long c : childrenOf(s, i)) todo.push_back(c);
    while (!todo.empty()) {
        const long c = todo.front();
        todo.pop_front();
        const int cs = scaleAt(s, c, scaleOf);
        if (cs > current) {
            if (!scale || cs == *scale) out.push_back(c);
            for (long k : childrenOf(s, size_t(c))) todo.push_back(k);
        }
    }
    return out;
}

long successorAtScale(const LString& s, size_t i, int scale, const Scale& scaleOf) {
    int previous = scaleOf(s[i].cls);
    long p = directSonOf(s, i);
    if (!(scale > previous)) {  // a successor, not a component: past the successor's components
        while (p >= 0 && scaleAt(s, p, scaleOf) > scale) p = directSonOf(s, size_t(p));
        if (p < 0) return -1;
    }
    if (p < 0) return -1;
    int current = scaleAt(s, p, scaleOf);
    if (current < scale) {  // down into the components
        do {
            p = directSonOf(s, size_t(p));
            if (p < 0) return -1;
            previous = current;
            current = scaleAt(s, p, scaleOf);
        } while (current > previous && current < scale);
    }
    return scaleAt(s, p, scaleOf) == scale ? p : -1;
}

long predecessorAtScale(const LString& s, size_t i, int scale, const Scale& scaleOf, const Skip& skip) {
    if (i == 0) return -1;
    const int previous = i < s.size() ? scaleOf(s[i].cls) : INT_MAX;
    long p = parentOf(s, i, skip);
    if (p < 0) return -1;
    int current = scaleAt(s, p, scaleOf);
    if (!(scale < previous)) {  // a predecessor, not a complex: up out of the components
        while (current < previous) {
            p = parentOf(s, size_t(p), skip);
            if (p < 0) return -1;
            current = scaleAt(s, p, scaleOf);
        }
    }
    while (current > scale) {  // past the predecessor's components, to its complex at this scale
        p = parentOf(s, size_t(p), skip);
        if (p < 0) return -1;
        current = scaleAt(s, p, scaleOf);
    }
    return current == scale ? p : -1;
}

long successorAtLevel(const LString& s, size_t i, int scale, const Scale& scaleOf) {
    long p = directSonOf(s, i);
    while (p >= 0 && scaleAt(s, p, scaleOf) != scale) p = directSonOf(s, size_t(p));
    return p;
}

long predecessorAtLevel(const LString& s, size_t i, int scale, const Scale& scaleOf, const Skip& skip) {
    long p = parentOf(s, i, skip);
    while (p >= 0 && scaleAt(s, p, scaleOf) != scale) p = parentOf(s, size_t(p), skip);
    return p;
}

}  // namespace sprout::lpy::tree
