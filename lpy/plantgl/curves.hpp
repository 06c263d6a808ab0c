#pragma once
// PlantGL's curves and the functions made from them, evaluated as L-Py's PlantGL evaluates
// them: the only evaluation of Sprout's curves, patches and volumes (de Boor, knots, arc
// length); lpy/plantgl/plantgl_curves.py's classes keep PlantGL's interface and call this
// through lpy/plantgl/bind_curves.cpp. Every operation is written in the order of the Python
// it replaced (checked against the real PlantGL), so that the numbers are the same to the last
// bit.
#include <array>
#include <utility>
#include <vector>

namespace sprout::curves {

// A point of a curve: x, y and (for a 3D curve) z; z is 0 in 2D.
using Point = std::array<double, 3>;

// A NURBS curve of dimension 2 or 3 (PlantGL's NurbsCurve2D, NurbsCurve, BezierCurve2D).
class Nurbs {
public:
    // `ctrl`: dim + 1 numbers a point, (x, y, [z,] weight), as the Python keeps them (not
    // premultiplied). Throws std::out_of_range where the Python would index past its lists
    // (too few knots for the points and degree, a negative degree, no points).
    Nurbs(int dim, int degree, std::vector<double> knots, std::vector<double> ctrl);

    int dim() const { return m_dim; }
    double firstKnot() const { return m_knots[m_degree]; }
    double lastKnot() const { return m_knots[m_count]; }

    Point pointAt(double u) const;
    // The point before its division by the weight: (x*w, y*w, [z*w,] w), w at index dim.
    std::array<double, 4> homogeneousAt(double u) const;
    // The d-th derivative (d <= 2 is what PlantGL gives; 0 past the degree).
    Point derivativeAt(double u, int d) const;
    // (T x C'') x T / |T|^4, T the first derivative (0 where T is).
    Point normalAt(double u) const;
    // PlantGL's LineicModel::getLength: the polyline through `stride` steps of u, corrected at
    // both ends when begin and end fall between them.
    double length(double begin, double end, double stride) const;
    // The polyline of getArcLengthToUMapping (fraction of the length, u) and of
    // getUToArcLengthMapping (u, fraction); each is then quantised (5 * stride samples).
    std::vector<std::array<double, 2>> arcLengthToU(int stride) const;
    std::vector<std::array<double, 2>> uToArcLength(int stride) const;
    // `n` points at evenly spaced parameters, first knot to last (points()).
    std::vector<Point> sample(int n) const;

private:
    // The `stride` steps of u after the first knot that the mappings walk: each u and the
    // distance of its point from the one before (kept where a step does not move, with
    // stayOnZero, as getArcLengthToUMapping keeps it).
    std::vector<std::array<double, 2>> strideSteps(int stride, bool stayOnZero) const;

    int m_dim, m_degree, m_count;   // m_count: the control points
    std::vector<double> m_knots;
    std::vector<double> m_weighted;  // (x*w, y*w, [z*w,] w) a point
};

// A 2D polyline, point i at u = i (PlantGL's Polyline2D.getPointAt).
class Polyline2D {
public:
    explicit Polyline2D(std::vector<std::array<double, 2>> points);
    double firstKnot() const { return 0.0; }
    double lastKnot() const { return double(m_points.size() - 1); }
    Point pointAt(double u) const;

private:
    std::vector<std::array<double, 2>> m_points;
};

// PlantGL's QuantisedFunction: `sampling` (at least 3) values at evenly spaced x over the
// curve's x range, each found by bisecting the parameter until x is within 1e-5.
struct Quantised {
    double firstx = 0, lastx = 0;
    std::vector<double> values;

    double operator()(double x) const;  // linear between the samples, x clamped
};
Quantised quantise(const Nurbs& curve, int sampling);
Quantised quantise(const Polyline2D& curve, int sampling);

// A NURBS surface (PlantGL's NurbsPatch as the Python evaluates it): each row of control
// points a 3D NURBS curve along v, its points at v the control points (weight 1) of a curve
// along u. Rows and their points as the Python's constructor makes them.
class NurbsPatch {
public:
    // `rows`: each a row's (x, y, z, w) points; knots empty for the uniform clamped ones.
    NurbsPatch(std::vector<std::vector<double>> rows, int udegree, int vdegree, std::vector<double> uknots,
               std::vector<double> vknots);
    Point pointAt(double u, double v) const;
    // The (n + 1)^2 points at (i / n, j / n), i outer (the drawing's grid of triangles).
    std::vector<Point> grid(int n) const;

private:
    std::vector<double> column(double v) const;  // the curve along u at v, as control points
    Nurbs along(const std::vector<double>& column) const;

    std::vector<Nurbs> m_rows;
    int m_udegree;
    std::vector<double> m_uknots;
};

// A NURBS volume (PlantGL's nurbspatch_nd.NurbsPatch3D): control points (x, y, z, w) in a
// grid [u][v][w]. A point: de Boor at w on the homogeneous points of each line, the results
// of each plane at v, then the planes' at u (each parameter clamped to its knots).
class NurbsVolume {
public:
    using Grid = std::vector<std::vector<std::vector<std::array<double, 4>>>>;
    // Throws std::out_of_range where the knots or the degrees do not fit the points.
    NurbsVolume(Grid ctrl, std::array<int, 3> degrees, std::array<std::vector<double>, 3> knots);
    Point pointAt(double u, double v, double w) const;

private:
    Grid m_ctrl;
    std::array<int, 3> m_degrees;
    std::array<std::vector<double>, 3> m_knots;
};

// The uniform clamped knots of `n` control points: degree + 1 zeros, the inner knots evenly
// spaced, degree + 1 ones (a curve's and a volume's default knots; plantgl_curves.py asks here).
std::vector<double> uniformClampedKnots(int n, int degree);

// A point of the B-spline that (x, y, z, w) points make taken as (xw, yw, zw, w), at t clamped
// to the knots: (x, y, z, w), or the homogeneous point where w is 0 (a patch's iso sections,
// as PlantGL makes them; plantgl_patches.py asks here). Throws std::out_of_range where the
// knots are too few for the points and degree.
std::array<double, 4> weightedPointAt(const std::vector<std::array<double, 4>>& points, int degree,
                                      const std::vector<double>& knots, double t);

}  // namespace sprout::curves
