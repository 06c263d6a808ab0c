#pragma once
// A string as L-Py's axial tree (src/cpp/axialtree_manip.h): a module's parent, sons, complex
// and components at a scale, for the Python API's Lstring and Module (lpy/api/types.cpp)
// and the engine's multiscale contexts (lpy/engine/scales.cpp). Positions are indices; -1 is
// none. Brackets have no scale (INT_MAX, L-Py's DEFAULT_SCALE). `skip`, when given, names the
// classes a context passes over (consider: / ignore:).
#include <functional>
#include <vector>

#include "lpy/engine/lstring.hpp"

namespace sprout::lpy::tree {

using Scale = std::function<int(int cls)>;
using Skip = std::function<bool(int cls)>;

bool isPush(const LModule& m);
bool isPop(const LModule& m);
long parentOf(const LString& s, size_t i, const Skip& skip = nullptr);
long directSonOf(const LString& s, size_t i);
std::vector<long> lateralSonsOf(const LString& s, size_t i);
std::vector<long> childrenOf(const LString& s, size_t i);  // lateral sons, then the direct son
long complexOf(const LString& s, size_t i, int scale, const Scale& scaleOf);
// Components of i (modules of finer scales below it), all or those at `scale`.
std::vector<long> componentsOf(const LString& s, size_t i, const Scale& scaleOf, const int* scale = nullptr);
long successorAtScale(const LString& s, size_t i, int scale, const Scale& scaleOf);
// `i` may be s.size() (a new left context: the module being made has no scale yet).
long predecessorAtScale(const LString& s, size_t i, int scale, const Scale& scaleOf, const Skip& skip = nullptr);
long successorAtLevel(const LString& s, size_t i, int scale, const Scale& scaleOf);
long predecessorAtLevel(const LString& s, size_t i, int scale, const Scale& scaleOf, const Skip& skip = nullptr);

}  // namespace sprout::lpy::tree
