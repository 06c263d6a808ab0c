#pragma once
// L-Py's strings in C++ (lpy/engine/engine.hpp derives them): a module with its Python values
// (LModule) and a string of them (LString); the native path's string of plain numbers
// (NumString); and the Python views of them (PyLstring, PyModule, PyModuleClass), which
// api/types.cpp gives Python as Lstring, Module and ModuleClass.
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <pybind11/pybind11.h>

#include "core/base/pod_buffer.hpp"
#include "core/base/recycled.hpp"

namespace sprout::lpy {

namespace py = pybind11;

struct LModule {
    int cls = 0;
    py::tuple args;  // empty when the module has none
    // Where it came from ("why this branch?"): the rule that made it at this step (an index
    // of Translation::rules; -1 copied unchanged or made by Python), and its module in the
    // step before (in the string an interpretation read, for an interpreted module).
    std::int32_t rule = -1;
    std::uint32_t parent = 0;
};
// Its buffers come back to the next derivation (core/base/recycled.hpp): every step is kept,
// and a plant dropped and opened again took its pages from the kernel anew.
using LString = std::vector<LModule, recycled::Allocator<LModule>>;

// A string of the native path (lpy/engine/native_derive.cpp): each module is its shape (class, count of
// numbers, which of them Python holds as ints), 4 bytes, and the numbers of all modules are in
// one array, in order: module k's follow module k - 1's. No Python objects. Drawn and written
// as it is; made into an LString only where Python reads it (the interpretation rules, growth
// stepping). A step reads and writes half the bytes it did with 16-byte modules that held
// their class, numbers' offset and count.
struct NumString {
    struct Shape {
        int cls = 0;
        std::uint32_t n = 0;     // its numbers
        std::uint32_t ints = 0;  // bit a: Python holds number a as an int
    };
    struct Origin {  // as LModule::rule and LModule::parent
        std::int32_t rule = -1;
        std::uint32_t parent = 0;
    };
    // No zeroing, and huge pages from 1 MB: a step writes its string once, into fresh
    // memory, and with 4 KB pages the kernel's page faults took more than half of it. From
    // 1 MB (not 2) the buffers come from the mappings kept between derivations, not from
    // malloc, whose choice between its heap and a fresh mapping for a buffer of 1-2 MB moves
    // with what the process freed before (lpy_bench's 18 steps ran at 150 or at 300 M
    // matches/s depending on how big a module the interpreter had compiled first).
    PodBuffer<std::uint32_t, (1u << 20)> modules;  // an index of `shapes` per module
    PodBuffer<double, (1u << 20)> params;
    PodBuffer<Origin, (1u << 20)> origins;  // one per module when kept, else none
    std::shared_ptr<const std::vector<Shape>> shapes;  // the derivation's, shared by its steps
    size_t size() const { return modules.size(); }
    const Shape& shape(size_t k) const { return (*shapes)[modules[k]]; }
    void swap(NumString& o) noexcept {
        modules.swap(o.modules);
        params.swap(o.params);
        origins.swap(o.origins);
        shapes.swap(o.shapes);
    }
};

// The string as Python sees it (hooks' `lstring`, L-Py's AxialTree), and one module of it: a
// view into a string (writes go to it) or a module of its own.
struct PyLstring {
    PyLstring() = default;
    explicit PyLstring(std::shared_ptr<LString> modules, std::shared_ptr<const NumString> numbers = nullptr)
        : s(std::move(modules)), pending(std::move(numbers)) {}
    std::shared_ptr<LString> s;
    // A native derivation's result (Lsystem.derive on the native path): its modules made only
    // when Python reads them (get()), so a derivation from a script costs what it costs from
    // the command line.
    mutable std::shared_ptr<const NumString> pending;
    LString& get() const;
    size_t size() const;
};
// L-Py's Lstring, the AxialTree a script makes (`Lstring('A B', context)`).
struct PyLstringMade : PyLstring {
    using PyLstring::PyLstring;
};
struct PyModule {
    std::shared_ptr<LString> owner;  // set: a view of (*owner)[index]
    size_t index = 0;
    LModule own;
    // A NodeModule (L-Py's are copies): its module is `own`, `owner` only tells its place.
    bool detached = false;
    LModule& get() { return owner && !detached ? (*owner)[index] : own; }
};

// L-Py's class tree: Module (a name), ParamModule (with parameters: every module Python gets
// from a string or makes), NodeModule (one bound in its string by `$A(a)` or AxialTree.node).
struct PyParamModule : PyModule {};
struct PyNodeModule : PyParamModule {};

// A module class as Python holds it. The handles alive on each class are counted
// (ModuleClass.getReferenceCount): they are made and dropped with the GIL held.
struct PyModuleClass {
    int cls = 0;
    PyModuleClass(int c = 0) : cls(c) { ++handles(cls); }
    PyModuleClass(const PyModuleClass& o) : cls(o.cls) { ++handles(cls); }
    PyModuleClass& operator=(const PyModuleClass& o) {
        --handles(cls);
        cls = o.cls;
        ++handles(cls);
        return *this;
    }
    ~PyModuleClass() { --handles(cls); }
    static int& handles(int c) {
        static std::unordered_map<int, int> count;  // with the interpreter: its classes' handles
        return count[c];
    }
};

}  // namespace sprout::lpy
