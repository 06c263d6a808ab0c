// L-Py's query modules answered as L-Py's turtle answers them: the frame of PlantGL's turtle
// (src/cpp/plantgl/algo/modelling/turtle.cpp and turtleparam.cpp, at 6e01c6d), in double
// precision and in L-Py's axes, walked over the drawable grammar of a query walk
// (drawable(..., queries = true)). Sprout's own turtle (core/turtle) works in single
// precision, which keeps big strings fast to draw, but a frame read back from it differed from
// L-Py's in the sixth digit; this walk keeps only the frame, as PlantGL computes it: each
// rotation a Matrix3::axisRotation of PlantGL's GEOM_RAD (0.01745329252, not pi / 180), the
// vectors' operations in PlantGL's order, its GEOM_EPSILON (1e-5) and GEOM_TOLERANCE (1e-10).
// Built with -ffp-contract=off (lpy/CMakeLists.txt): each product rounded as PlantGL rounds it.
#include <cmath>
#include <vector>

#include "lpy/draw/draw_impl.hpp"

namespace sprout::lpy::detail {
namespace {

using V = glm::dvec3;
constexpr double kEpsilon = 1e-5;     // PlantGL's GEOM_EPSILON
constexpr double kTolerance = 1e-10;  // GEOM_TOLERANCE
constexpr double kRad = 0.01745329252;  // GEOM_RAD

// PlantGL's Vector3 functions (util_vector.cpp), in its order of operations.
double dot(const V& a, const V& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V cross(const V& a, const V& b) { return V(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x); }
double norm(const V& v) { return std::sqrt(dot(v, v)); }
V divided(const V& v, double s) { return V(v.x / s, v.y / s, v.z / s); }
double normalize(V& v) {  // Vector3::normalize: the norm it had
    const double n = norm(v);
    if (n > kTolerance) v = divided(v, n);
    return n;
}
V direction(const V& v) {  // Vector3::normed
    const double n = norm(v);
    return n < kEpsilon ? v : divided(v, n);
}

// Matrix3::axisRotation and Matrix3 * Vector3 (util_matrix.cpp).
struct Rotation {
    double m[9];
    V operator*(const V& v) const {
        return V(m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z, m[6] * v.x + m[7] * v.y + m[8] * v.z);
    }
};
Rotation axisRotation(const V& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    const double x = axis.x, y = axis.y, z = axis.z;
    const double sx = s * x, sy = s * y, sz = s * z;
    const double txx = t * x * x, txy = t * x * y, txz = t * x * z, tyy = t * y * y, tyz = t * y * z, tzz = t * z * z;
    return {{txx + c, txy - sz, txz + sy, txy + sz, tyy + c, tyz - sx, txz - sy, tyz + sx, tzz + c}};
}

// What the drawable grammar's modules are to PlantGL's turtle.
enum class Op : std::uint8_t {
    None, F, f, Left, Right, Up, Down, RollL, RollR, Around, Vertical, Push, Pop, Tropism,
    SetHead, MoveTo, MoveRel, Pinpoint, PinpointRel, LineTo, OLineTo, LineRel, OLineRel, Query,
};
Op opOf(const std::string& name) {
    static const std::pair<const char*, Op> table[] = {
        {"F", Op::F}, {"f", Op::f}, {"+", Op::Left}, {"-", Op::Right}, {"^", Op::Up}, {"&", Op::Down},
        {"\\", Op::RollL}, {"/", Op::RollR}, {"|", Op::Around}, {"$", Op::Vertical}, {"[", Op::Push},
        {"]", Op::Pop}, {"@T", Op::Tropism}, {"@R", Op::SetHead}, {"@M", Op::MoveTo}, {"MoveRel", Op::MoveRel},
        {"Pinpoint", Op::Pinpoint}, {"PinpointRel", Op::PinpointRel}, {"LineTo", Op::LineTo}, {"OLineTo", Op::OLineTo},
        {"LineRel", Op::LineRel}, {"OLineRel", Op::OLineRel}, {"?P", Op::Query},
    };
    for (const auto& [n, op] : table)
        if (name == n) return op;
    return Op::None;
}

// PlantGL's turtle, its frame only (TurtleParam's position, heading, left, up).
class PglTurtle {
public:
    explicit PglTurtle(double angle) : m_angle(angle) {}

    PglFrame frame() const { return {m_f.position, m_f.heading, m_f.up, m_f.left}; }

    void left(double angle) { turn(m_f.up, m_f.heading, m_f.left, angle); }
    void down(double angle) { turn(m_f.left, m_f.heading, m_f.up, angle); }
    void rollL(double angle) { turn(m_f.heading, m_f.up, m_f.left, angle); }
    void turnAround() { left(180); }
    double angle() const { return m_angle; }

    // F: the tropism (the module before it, @T, when the elasticity is set) applied first,
    // then the move; a length under GEOM_EPSILON moves nothing, a negative one goes back.
    void F(double length) {
        if (length > 0) {
            applyTropism();
            if (length > kEpsilon) m_f.position += m_f.heading * length * 1.0;  // * getScale().z()
        } else if (length < -kEpsilon) {
            turnAround();
            F(-length);
            turnAround();
        }
        m_tropism.reset();
    }
    void f(double length) {
        applyTropism();
        m_tropism.reset();
        m_f.position += m_f.heading * length * 1.0;
    }
    // @T(e, x, y, z, 1): the tropism and elasticity the next F or f applies (setTropism normalizes).
    void tropism(double elasticity, const V& towards) { m_tropism = {elasticity, direction(towards)}; }

    void rollToVert() {  // alpha 1, top OZ
        m_f.left = cross(V(0, 0, 1), m_f.heading);
        if (norm(m_f.left) < kEpsilon) m_f.left = V(0, -1, 0);
        else normalize(m_f.left);
        m_f.up = cross(m_f.heading, m_f.left);
    }
    // L-Py's SetHead module (predefinedmodules.cpp): the heading normalized; without an up, the
    // least rotation to it (pinpointRel); with one, PlantGL's setHead.
    void setHeadModule(V h, const V* up) {
        if (normalize(h) < kEpsilon) return;
        if (!up) return pinpointRel(h);
        V u = *up;
        if (normalize(u) < kEpsilon) return pinpointRel(h);
        setHead(h, u);
    }
    void move(const V& to) { m_f.position = to; }
    void shift(const V& by) { m_f.position += by; }
    void pinpoint(const V& at) { pinpointRel(at - m_f.position); }
    void pinpointRel(V h) {
        if (normalize(h) > kEpsilon) tendTo(h, 1);
    }
    // oLineTo, oLineRel (the heading turned to the point, then F to it); lineTo and lineRel
    // keep the frame they had.
    void oLineRel(V h) {
        const double l = normalize(h);
        if (l > kEpsilon) {
            tendTo(h, 1);
            F(l);  // the tropism (@T before it) applied after the turn, as F applies it
        }
        m_tropism.reset();
    }
    void oLineTo(const V& to) { oLineRel(to - m_f.position); }
    void lineRel(const V& h) { keepingFrame([&] { oLineRel(h); }); }
    void lineTo(const V& to) { keepingFrame([&] { oLineTo(to); }); }

    void push() { m_stack.push_back(m_f); }
    void pop() {
        if (m_stack.empty()) return;
        m_f = m_stack.back();
        m_stack.pop_back();
    }

private:
    struct Frame {
        V position{0, 0, 0}, heading{0, 0, 1}, left{0, -1, 0}, up{1, 0, 0};
    };
    struct Tropism {
        double elasticity;
        V towards;
    };

    // left, down and rollL: about `axis` by the angle in degrees, `a` and `b` turned.
    static void turn(const V& axis, V& a, V& b, double degrees) {
        const Rotation m = axisRotation(axis, degrees * kRad);
        a = m * a;
        b = m * b;
    }
    void transform(const Rotation& m) {
        m_f.heading = m * m_f.heading;
        m_f.left = m * m_f.left;
        m_f.up = m * m_f.up;
    }
    void tendTo(const V& t, double strength) {  // Turtle::_tendTo
        const V h = m_f.heading;
        V cp = cross(h, t);
        const double sinus = norm(cp);
        if (sinus > kEpsilon) {
            cp = divided(cp, sinus);
            const double cosinus = dot(h, t);
            const double ang = std::atan2(sinus, cosinus);
            transform(axisRotation(cp, ang * strength));
        } else if (dot(h, t) < kEpsilon) {
            transform(axisRotation(m_f.up, M_PI * strength));
        }
    }
    void applyTropism() {
        if (m_tropism && m_tropism->elasticity > kEpsilon) tendTo(m_tropism->towards, m_tropism->elasticity);
    }
    void setHead(V h, V u) {  // Turtle::setHead
        normalize(h);
        normalize(u);
        const V l = cross(u, h);
        if (!(std::fabs(dot(h, u)) < kEpsilon)) u = cross(h, l);
        m_f.heading = h;
        m_f.up = u;
        m_f.left = l;
    }
    template <class Move>
    void keepingFrame(Move move) {
        const V heading = m_f.heading, left = m_f.left, up = m_f.up;
        move();
        m_f.heading = heading, m_f.left = left, m_f.up = up;
    }

    double m_angle;
    Frame m_f;
    std::vector<Frame> m_stack;
    std::optional<Tropism> m_tropism;
};

}  // namespace

std::vector<PglFrame> queryFrames(const Grammar& g) {
    std::vector<Op> ops(g.alphabet.size(), Op::None);
    for (size_t s = 0; s < g.alphabet.size(); ++s) ops[s] = opOf(g.alphabet[SymbolId(s)].name);
    std::vector<PglFrame> frames;
    PglTurtle t(g.settings.angle.mean);
    const ModuleString& str = g.axiom;
    const double* p = str.params.data();
    for (size_t k = 0; k < str.size(); ++k) {
        const SymbolId s = str.symbols[k];
        const int n = g.alphabet[s].arity;
        const double* q = p;
        p += n;
        // Sprout's axes (x, y, z) are L-Py's (y, z, x): a point as L-Py's.
        auto point = [&](int at) { return V(q[at + 2], q[at], q[at + 1]); };
        const double angle = n >= 1 ? q[0] : t.angle();
        switch (ops[s]) {
            case Op::F: t.F(n >= 1 ? q[0] : 1.0); break;
            case Op::f: t.f(n >= 1 ? q[0] : 1.0); break;
            case Op::Left: t.left(angle); break;
            case Op::Right: t.left(-angle); break;
            case Op::Up: t.down(-angle); break;
            case Op::Down: t.down(angle); break;
            case Op::RollL: t.rollL(angle); break;
            case Op::RollR: t.rollL(-angle); break;
            case Op::Around: t.turnAround(); break;
            case Op::Vertical: t.rollToVert(); break;
            case Op::Push: t.push(); break;
            case Op::Pop: t.pop(); break;
            case Op::Tropism:  // @T(e, x, y, z, 1), as Drawing::bend writes it
                if (n >= 5) t.tropism(q[0], point(1));
                break;
            case Op::SetHead:
                if (n >= 6) {
                    const V up = point(3);
                    t.setHeadModule(point(0), &up);
                } else if (n >= 3) {
                    t.setHeadModule(point(0), nullptr);
                }
                break;
            case Op::MoveTo:
                if (n >= 3) t.move(point(0));
                break;
            case Op::MoveRel:
                if (n >= 3) t.shift(point(0));
                break;
            case Op::Pinpoint:
                if (n >= 3) t.pinpoint(point(0));
                break;
            case Op::PinpointRel:
                if (n >= 3) t.pinpointRel(point(0));
                break;
            case Op::LineTo:
                if (n >= 3) t.lineTo(point(0));
                break;
            case Op::OLineTo:
                if (n >= 3) t.oLineTo(point(0));
                break;
            case Op::LineRel:
                if (n >= 3) t.lineRel(point(0));
                break;
            case Op::OLineRel:
                if (n >= 3) t.oLineRel(point(0));
                break;
            case Op::Query: frames.push_back(t.frame()); break;
            case Op::None: break;
        }
    }
    return frames;
}

}  // namespace sprout::lpy::detail
