"""The cases of tests/reference/plantgl_differential.py: Python run by the reference PlantGL and by
Sprout's, each leaving `result` (numbers, vectors, lists, dicts of them). Each case is (name,
code, relative tolerance): the numbers of the curves and vectors are PlantGL's own arithmetic,
compared to 1e-9; the light model's pixels depend on meshes and rays, compared looser."""

SPHERE_BOX = ("sc = Scene([Shape(Sphere(1), Material(), 3), Shape(Translated((0,0,3), Box((1,1,1))), Material(), 5)])\n")
TWO_SPHERES = ("sc = Scene([Shape(Sphere(1), Material(), 1), Shape(Translated((0,0,3), Sphere(1)), Material(), 2)])\n")
SQUARE = ("sq = TriangleSet([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,2),(0,2,3)])\n"
          "sc = Scene([Shape(sq, Material(), 7), Shape(Translated((0.25,0.25,1), Scaled((0.5,0.5,1), sq)), Material(), 8)])\n")

# PlantGL's text scene files (.geom): each shape described by its fields, sorted by id (PlantGL's
# reader gives its shapes in an order of its own).
DESCRIBED = (
    "def desc(g):\n"
    "    t = type(g).__name__\n"
    "    if t == 'Shape':\n"
    "        return [t, g.id, desc(g.geometry), desc(g.appearance)]\n"
    "    if t == 'Material':\n"
    "        return [t, list(g.ambient), g.diffuse, list(g.specular), list(g.emission), g.shininess, g.transparency]\n"
    "    out = [t]\n"
    "    for f in ('radius', 'height', 'taper', 'slices', 'stacks', 'solid', 'size', 'translation', 'scale', 'axis',\n"
    "              'angle', 'azimuth', 'elevation', 'roll', 'primary', 'secondary'):\n"
    "        if hasattr(g, f):\n"
    "            v = getattr(g, f)\n"
    "            out.append([f, list(v) if hasattr(v, '__len__') else v])\n"
    "    if hasattr(g, 'geometry'): out.append(desc(g.geometry))\n"
    "    if hasattr(g, 'geometryList'): out.append([desc(x) for x in g.geometryList])\n"
    "    if hasattr(g, 'pointList'): out.append([list(p) for p in g.pointList])\n"
    "    if getattr(g, 'indexList', None) is not None: out.append([list(i) for i in g.indexList])\n"
    "    return out\n"
    "def described(path):\n"
    "    return sorted((desc(sh) for sh in Scene(path)), key=lambda d: d[1])\n")
# A file as PlantGL's printer writes one (written here by hand): named objects, a shared
# material, nested objects in place, a colour given as one number, a comment, angles in degrees.
GEOM_TEXT = (
    "# a scene\n"
    "Translated T1 {\n    Translation <1,2,3>\n    Geometry Oriented {\n        Primary <0,0,1>\n"
    "        Secondary <1,0,0>\n        Geometry Cylinder { Radius 0.1 Height 2.5 Solid False Slices 5 }\n    }\n}\n"
    "Material M1 {\n    Ambient <10,200,30>\n    Diffuse 1.2\n    Specular <5,6,7>\n    Emission 1\n"
    "    Shininess 0.5\n    Transparency 0.25\n}\n"
    "Shape S1 { Id 4 Geometry T1 Appearance M1 }\n"
    "AxisRotated A1 {\n    Axis <0,1,0>\n    Angle 30\n    Geometry Box { Size <1,2,3> }\n}\n"
    "Shape S2 { Id 9 Geometry A1 Appearance M1 }\n"
    "TriangleSet TS {\n    PointList [ <0,0,0>, <1,0.5,0>, <0,1,0.25> ]\n    IndexList [ [0,1,2] ]\n}\n"
    "Shape S3 {\n    Id 2\n    Geometry TS\n    Appearance Material { Ambient <1,2,3> }\n}\n"
    "Shape S4 { Id 7 Geometry EulerRotated { Azimuth 10 Elevation 20 Roll 30 Geometry Group {\n"
    "    GeometryList [ Sphere { Radius 1 Slices 9 }, Cone { Radius 1 Height 2 } ] } } Appearance M1 }\n")
GEOM_FILE = ("import tempfile, os\nd = tempfile.mkdtemp()\npath = os.path.join(d, 'scene.geom')\n"
             "open(path, 'w').write(%r)\n" % GEOM_TEXT)
SCENE_TO_SAVE = (
    "import tempfile, os\n"
    "m = Material((10,200,30))\nm.diffuse = 1.2\nm.specular = Color3(5,6,7)\nm.shininess = 0.5\n"
    "sc = Scene([Shape(Translated(Vector3(1,2,3), Oriented(Vector3(0,0,1), Vector3(1,0,0), Cylinder(0.1, 2.5))), m, 100),\n"
    "            Shape(AxisRotated((0,1,0), 1.0, Box((1,2,3))), Material((1,2,3)), 101),\n"
    "            Shape(EulerRotated(0.1, 0.2, 0.3, Disc(0.3, 12)), m, 102),\n"
    "            Shape(Group([Sphere(1), Cone(1, 2)]), m, 103), Shape(Frustum(0.3, 2, 0.25), m, 104),\n"
    "            Shape(QuadSet([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,2,3)]), m, 105),\n"
    "            Shape(Scaled((2,2,2), Translated((1,0,0), Sphere(0.7, 9, 11))), m, 106),\n"
    "            Shape(Polyline([(0,0,0),(1,1,1)]), m, 107)])\n"
    "d = tempfile.mkdtemp()\npath = os.path.join(d, 'saved.geom')\nsc.save(path)\n")

CASES = [
    # openalea.plantgl.scenegraph.cspline
    ("cspline 3D control points, knots, stride",
     "from openalea.plantgl.scenegraph.cspline import CSpline\n"
     "n = CSpline([Vector3(0,0,0),Vector3(1,1,0),Vector3(2,0,1),Vector3(3,2,2)]).curve()\n"
     "result = [type(n).__name__, list(n.ctrlPointList), list(n.knotList), n.stride, n.degree]", 1e-12),
    ("cspline 2D from tuples",
     "from openalea.plantgl.scenegraph.cspline import cspline\n"
     "n = cspline([(0,0),(1,2),(3,1),(4,4)])\n"
     "result = [type(n).__name__, list(n.ctrlPointList), list(n.knotList), n.stride]", 1e-12),
    ("cspline closed",
     "from openalea.plantgl.scenegraph.cspline import cspline\n"
     "n = cspline([Vector3(0,0,0),Vector3(1,0,0),Vector3(1,1,0),Vector3(0,1,0)], is_closed=True)\n"
     "result = [list(n.ctrlPointList), list(n.knotList), n.stride]", 1e-12),
    ("cspline linear parameters, given distances, stride factor",
     "from openalea.plantgl.scenegraph.cspline import CSpline\n"
     "c = CSpline([Vector3(0,0,0),Vector3(2,1,0),Vector3(3,3,1)])\n"
     "a = c.curve(is_linear=True)\n"
     "c2 = CSpline([Vector3(0,0,0),Vector3(2,1,0),Vector3(3,3,1)])\n"
     "b = c2.curve(distances=[1., 3.], stride_factor=4)\n"
     "result = [list(a.knotList), a.stride, list(b.knotList), b.stride, len(c), c.dist, list(c.der)]", 1e-12),
    ("cspline curve evaluated",
     "from openalea.plantgl.scenegraph.cspline import cspline\n"
     "n = cspline([Vector3(0,0,0),Vector3(1,1,0),Vector3(2,0,1),Vector3(3,2,2)])\n"
     "us = [n.firstKnot + (n.lastKnot - n.firstKnot) * i / 7. for i in range(8)]\n"
     "result = [[n.getPointAt(u) for u in us], [n.getTangentAt(u) for u in us], n.getLength(), n.firstKnot, n.lastKnot]",
     1e-9),
    ("cspline as NurbsCurve.CSpline",
     "n = NurbsCurve.CSpline([Vector3(0,0,0),Vector3(0,1,1),Vector3(1,2,1)])\n"
     "result = [list(n.ctrlPointList), list(n.knotList)]", 1e-12),
    ("cspline errors",
     "from openalea.plantgl.scenegraph.cspline import CSpline\n"
     "c = CSpline([Vector3(0,0,0),Vector3(1,0,0)], is_closed=True)\n"
     "try:\n    c.add_point(Vector3(1,1,1)); r1 = 'no error'\nexcept Exception as e:\n    r1 = str(e)\n"
     "try:\n    c.move_point(5, Vector3(1,1,1)); r2 = 'no error'\nexcept Exception as e:\n    r2 = str(e)\n"
     "result = [r1, r2, len(c)]", 0),
    # curves' members
    ("NurbsCurve2D members",
     "c = NurbsCurve2D([(0,0,1),(1,2,1),(2,-1,1),(3,1,1),(4,0,1)])\n"
     "result = [c.degree, c.firstKnot, c.lastKnot, c.stride, list(c.knotList), c.getPointAt(0.3), c.getTangentAt(0.3),"
     " c.getNormalAt(0.3), c.getLength()]", 1e-9),
    ("NurbsCurve members",
     "c = NurbsCurve([(0,0,0,1),(1,2,0,1),(2,-1,1,2),(3,1,2,1)], degree=2)\n"
     "m = c.getArcLengthToUMapping()\n"
     "result = [c.degree, c.firstKnot, c.lastKnot, list(c.knotList), c.getPointAt(0.5), c.getTangentAt(0.5),"
     " c.getNormalAt(0.5), c.getLength(), m(0.25), m(0.5)]", 1e-9),
    ("BezierCurve2D",
     "c = BezierCurve2D([(0,0,1),(1,2,1),(3,0,1)])\n"
     "result = [c.getPointAt(0.25), c.getTangentAt(0.25), c.getLength(), c.firstKnot, c.lastKnot]", 1e-9),
    ("Polyline2D",
     "p = Polyline2D([(0,0),(1,0),(1,2)])\n"
     "result = [p.getPointAt(0.5), p.getPointAt(1.5), p.getPointAt(2)]", 1e-12),
    ("Polyline as a curve",
     "p = Polyline([(0,0,0),(1,0,0),(1,2,0),(1,2,3)])\n"
     "m = p.getArcLengthToUMapping()\n"
     "result = [p.firstKnot, p.lastKnot, p.stride, p.getPointAt(1.5), p.getTangentAt(1), p.getTangentAt(1.5),"
     " p.getNormalAt(2.5), p.getLength(), p.getLength(0.5, 2.5), m(0.5), p.isACurve(), p.isExplicit()]", 1e-9),
    ("Polyline2D members",
     "p = Polyline2D([(0,0),(3,0),(3,4)])\n"
     "result = [p.getTangentAt(1), p.getNormalAt(0.5), p.getLength(), p.stride, p.lastKnot]", 1e-9),
    ("BezierCurve 3D",
     "c = BezierCurve([(0,0,0,1),(1,2,0,1),(3,0,1,1),(4,1,0,1)])\n"
     "result = [c.getPointAt(0.3), c.getTangentAt(0.3), c.getLength(), c.firstKnot, c.lastKnot, c.stride]", 1e-9),
    ("NURBS knots' defaults",
     "c = NurbsCurve2D([(0,0,1),(1,2,1),(2,-1,1),(3,1,1),(4,0,1)])\n"
     "d = NurbsCurve2D([(0,0,1),(1,2,1),(2,-1,1),(3,1,1)], knotList=[0,0,0,0,2,2,2,2])\n"
     "result = [c.isKnotListToDefault(), d.isKnotListToDefault(), c.isDegreeToDefault(), c.isStrideToDefault(),"
     " list(NurbsCurve.defaultKnotList(6, 2)), NurbsCurve([(0,0,0,1),(1,2,0,1),(2,-1,1,1),(3,1,0,1)]).getDerivativeAt(0.4, 2)]", 1e-9),
    ("scene objects' defaults and kinds",
     "s, c, t = Sphere(), Cylinder(), Translated((1,2,3), Box())\n"
     "result = [s.radius, s.slices, s.stacks, c.height, c.solid, t.translation, Box().size, Scaled(geometry=Sphere()).scale,"
     " AxisRotated(geometry=Sphere()).axis, Sphere.DEFAULT_RADIUS, Cylinder.DEFAULT_HEIGHT, AsymmetricHull.DEFAULT_NEG_X_RADIUS,"
     " s.isRadiusToDefault(), Sphere(2).isRadiusToDefault(), t.isTranslationToDefault(), s.getName(), s.isNamed(),"
     " Box().isAVolume(), s.isACurve(), Disc().isASurface(), Polyline([(0,0,0),(1,0,0)]).isACurve(),"
     " TriangleSet([(0,0,0),(1,0,0),(0,1,0)],[(0,1,2)]).isExplicit(), Sphere().isExplicit(), s.isValid()]", 0),
    ("Shape's id and name",
     "sh = Shape(Sphere(), Material(), 5)\n"
     "result = [sh.id, sh.name.startswith('SHAPEID_5_'), Shape(Sphere()).id != Shape.NOID, Shape.NOID,"
     " sh.appearance.name.startswith('APPID_5_'), Shape(Sphere()).appearance.name, sh.geometry.name.startswith('GEOMID_5_')]", 0),
    ("colours and materials",
     "c, d = Color3(10,20,30), Color4(1,2,3,4)\n"
     "m = Material('m', (10,20,30), 1.5)\n"
     "result = [Color3.RED, Color4.BLUE, c.clampedRed(), d.clampedAlpha(), d.getAverage(), c.toUint(), d.toUint(),"
     " Color3.fromUint(0x0a141e), Color4.fromUint(337520650), d.alpha, m.diffuseColor(), Material().diffuseColor(), Material.DEFAULT_AMBIENT,"
     " Material().isAmbientToDefault(), m.isAmbientToDefault(), Material.DEFAULT_MATERIAL.name, m.name]", 1e-12),
    ("scene's find and merge",
     "a, b = Shape(Sphere(), Material(), 1), Shape(Box(), Material(), 2)\n"
     "sc = Scene([a]); sc.merge(Scene([b]))\n"
     "try:\n    sc.find(7); missing = 'found'\nexcept IndexError:\n    missing = 'IndexError'\n"
     "result = [len(sc), sc.find(2).geometry.size, missing]", 0),
    ("point arrays' members",
     "a = Point3Array([(3,0,1),(1,2,-1),(2,-1,5)])\n"
     "b = Point3Array(a); b.translate(Vector3(1,1,1))\n"
     "c = Point3Array(a); c.scale(Vector3(1,2,3))\n"
     "d = Point3Array(a); d.transform(Matrix3.scaling(2))\n"
     "e = Point3Array(a); e.prepend(Vector3(9,9,9))\n"
     "f = Point3Array(a); f.sortX()\n"
     "result = [a.getLength(), a.getExtent(), a.getXMinIndex(), a.getXMaxIndex(), list(a.getZMinAndMaxIndex()),"
     " list(a.getBounds()), a.getCenter(), b, c, d, e, f, a.subset([0,2]), a.opposite_subset([0]), list(a.findClosest(Vector3(1,1,0))),"
     " a.empty(), a.isValid(), Point2Array([(0,0),(3,4)]).getLength()]", 1e-12),
    ("RealArray's members",
     "r = RealArray([3,1,2])\n"
     "result = [r.getMin(), r.getMax(), r.getMean(), r.getSum(), r.getMinIndex(), r.getMaxIndex(), list(r.getMinAndMax()),"
     " list(r.getMinAndMaxIndex()), r.sqrt(), r.log(), r.pow(2), r.exp()]", 1e-12),
    ("meshes' members",
     "t = TriangleSet([(0,0,0),(1,0,0),(1,1,0),(0,1,1)], [(0,1,2),(0,2,3)])\n"
     "q = QuadSet([(0,0,0),(1,0,0),(1,1,0),(0,1,1)], [(0,1,2,3)], ccw=False, solid=True)\n"
     "result = [t.pointAt(1), t.pointAt(1,2), list(t.indexAt(1)), t.indexListSize(), t.faceCenter(1), t.faceSize(1),"
     " list(q.indexAt(0)), q.faceSize(0), q.faceCenter(0), q.pointAt(0,3), t.ccw, t.solid, q.ccw, q.solid,"
     " t.isCCWToDefault(), q.isCCWToDefault(), q.isSolidToDefault(), t.normalList, t.colorList, t.normalPerVertex,"
     " TriangleSet.DEFAULT_CCW, TriangleSet.DEFAULT_SOLID, TriangleSet.DEFAULT_NORMALPERVERTEX,"
     " TriangleSet.DEFAULT_COLORPERVERTEX, t.isASurface(), t.isExplicit()]", 1e-12),
    ("NurbsPatch members",
     "rows = [[(0,0,0,1),(0,1,0,1),(0,2,1,1)],[(1,0,1,1),(1,1,2,1),(1,2,0,1)],[(2,0,0,1),(2,1,1,1),(2,2,2,1)]]\n"
     "p = NurbsPatch(rows, udegree=2, vdegree=2)\n"
     "w = NurbsPatch([[(0,0,0,1),(0,1,0,2),(0,2,1,1)],[(1,0,1,1),(1,1,2,1),(1,2,0,3)]], udegree=1, vdegree=2)\n"
     "result = [p.getPointAt(0.3,0.6), p.getUTangentAt(0.3,0.6), p.getVTangentAt(0.3,0.6), list(p.getIsoUSectionAt(0.3).ctrlPointList),"
     " list(p.getIsoVSectionAt(0.6).ctrlPointList), p.firstUKnot, p.lastUKnot, list(p.uknotList), p.ccw, p.ustride,"
     " w.getPointAt(0.4, 0.7), w.getUTangentAt(0.4, 0.7), w.getVTangentAt(0.4, 0.7), list(w.getIsoUSectionAt(0.4).ctrlPointList),"
     " p.isUDegreeToDefault(), p.isUKnotListToDefault(), NurbsPatch.DEFAULT_STRIDE]", 1e-9),
    ("QuantisedFunction members",
     "m = QuantisedFunction(NurbsCurve2D([(0,0,1),(0.3,0.2,1),(0.7,0.5,1),(1,1,1)]))\n"
     "q = QuantisedFunction(NurbsCurve2D([(0,0,1),(0.3,0.8,1),(0.7,0.2,1),(1,0.1,1)]))\n"
     "i = m.inverse()\n"
     "result = [m.isIncreasing(), m.isDecreasing(), m.isMonotonous(), m.isIncreasing(True), q.isMonotonous(), q.inverse(),"
     " m.findX(0.5), m.findX(2.0), m.findX(0.5, 0.9), i(0), i(0.5), i(0.99), i(1.0), i.firstx, i.lastx, i.sampling,"
     " m.clamped, QuantisedFunction.DEFAULT_SAMPLING, m.isClampedToDefault(),"
     " QuantisedFunction.checkQuantisableFunction(NurbsCurve2D([(0,0,1),(0.3,0.8,1),(0.7,0.2,1),(1,0.1,1)]))]", 1e-12),
    ("Point4Matrix members",
     "m = Point4Matrix([[(0,0,0,1),(0,1,0,1),(0,2,1,1)],[(1,0,1,1),(1,1,2,1),(1,2,0,1)]])\n"
     "a = [m.sizes(), m.size(), m.getRowNb(), m.getColumnNb(), m.getRowSize(), m.getColumnSize(), m.getRow(1), m.getColumn(2),"
     " m.empty(), m.isUnique(), m.transpose().sizes(), m.getDiagonal(), m[1,2]]\n"
     "m.pushRow([(5,5,5,1)]*3); m.pushColumn([(7,7,7,1)]*3); m.insertRow(0, [(9,9,9,1)]*4)\n"
     "result = a + [m.sizes(), m.getRow(0), m.getColumn(3), Point4Matrix([[(1,1,1,1),(1,1,1,1)]]).isUnique()]", 0),
    ("Grid3Indexing and Point3Grid",
     "g = Grid3Indexing((0.5,0.5,0.5), (0,0,0), (2,1,1.2))\n"
     "p = Point3Grid((0.5,0.5,0.5), [(0,0,0),(1,1,1),(2,0.3,0.7),(0.2,0.2,0.2)])\n"
     "result = [g.dimensions(), g.size(), g.getUpperCorner(), g.getGridSize(), g.cellId((1,2,1)), g.index(17), g.indexFromPoint((1.2,0.7,0.3)),"
     " g.cellIdFromPoint((1.2,0.7,0.3)), g.getVoxelCenterFromId(17), g.getVoxelLowerPointFromId(5), g.getVoxelUpperPoint((1,1,1)),"
     " g.isValidId(44), g.isValidId(45), g.isValidIndex((4,2,2)), g.isValidIndex((5,0,0)), g.getCorners(), g.getVoxelCorners((1,0,2)),"
     " g.getMaxIndexDistanceToBorder((1,2,0)), g.getMaxDistanceToBorder(Vector3(0.3,0.2,0.1)), g.indexFromCoord(1.3, 0),"
     " g.query_voxels_around_point((1,0.5,0.5), 0.6), g.query_voxels_in_cone((0,0,0),(1,1,1),1.5,1.0),"
     ""
     " p.dimensions(), p.getUpperCorner(), p.cellIdFromPoint((2,0.3,0.7)), p.getVoxelCenterFromId(3), p.isValidId(44), p.valuesize(), g.valuesize()]", 1e-12),
    ("findClosest on curves",
     "p = Polyline([(0,0,0),(1,0,0),(1,2,0)])\n"
     "c = NurbsCurve([(0,0,0,1),(1,2,0,1),(2,-1,1,1),(3,1,0,1)])\n"
     "d = NurbsCurve2D([(0,0,1),(1,2,1),(2,-1,1),(3,1,1)])\n"
     "result = [list(p.findClosest((2,1,0))), list(c.findClosest((2,1,0))), list(d.findClosest((2,1))),"
     " list(Polyline2D([(0,0),(2,0),(2,2)]).findClosest((3,1)))]", 1e-9),
    ("textures",
     "t = ImageTexture('x.png'); t2 = ImageTexture('n', 'y.png', False)\n"
     "x = Texture2D(t)\n"
     "result = [t.name, t.filename, t.mipmaping, t.repeatS, t.repeatT, ImageTexture.DEFAULT_MIPMAPING, t2.name, t2.filename,"
     " t2.mipmaping, x.image.filename, x.transformation, x.isTexture(), Texture2D.DEFAULT_BASECOLOR]", 0),
    # vectors, matrices
    ("Vector members",
     "v = Vector3(1,2,2)\n"
     "result = [v.x, v.y, v.z, norm(v), v.normed(), v.anOrthogonalVector(), Vector3(0,0,2).anOrthogonalVector(),"
     " Vector4(Vector3(1,2,3), 4), Vector3(Vector2(1,2), 5), dot(v, Vector3(1,0,1)), cross(v, Vector3(0,1,0))]", 1e-12),
    ("vector members PlantGL adds",
     "v, w = Vector3(1,-3,2), Vector3(0.5,2,1)\n"
     "result = [v.cwiseProduct(w), v.getMaxAbsCoord(), v.getMinAbsCoord(), Vector4(1,-5,2,5).getMaxAbsCoord(),"
     " Vector2(2,-2).getMinAbsCoord(), v.isNormalized(), Vector3(1,0,0).isNormalized(), v.isOrthogonalTo(Vector3(3,1,0)),"
     " v.reflect(w), v.refract(w, 1.5), v.anisotropicNorm(Vector3(1,2,3)), v.radialAnisotropicNorm(Vector3(0,0,1),1,2),"
     " Vector4(2,4,6,2).project(), Vector4(2,4,6,2).wtoxyz(), Vector2(Vector2.Polar(2, 0.5)), Vector3(2,4,2).project()]",
     1e-12),
    ("Matrix3 members",
     "m = Matrix3(1,2,3,4,5,6,7,8,10)\n"
     "e = Matrix3.eulerRotationZYX(Vector3(0.1,0.2,0.3)); x = Matrix3.eulerRotationXYZ(Vector3(0.1,0.2,0.3))\n"
     "result = [m.trace(), m.getDiagonal(), m.isOrthogonal(), m.isSingular(), m.adjoint().data(),"
     " Matrix3.scaling(Vector3(1,2,3)).data(), e.data(), x.data(), e.eulerAnglesZYX(), x.eulerAnglesXYZ(), m.data(),"
     " (m * m).data(), str(m)]", 1e-12),
    ("Matrix3 from columns, inverse, product",
     "m = Matrix3(Vector3(1,0,2), Vector3(0,3,0), Vector3(1,1,1))\n"
     "result = [m.getColumn(0), m.getRow(0), m.inverse().getRow(0), m.inverse().getRow(2), m * Vector3(1,2,3)]", 1e-12),
    # the light module's tools
    ("azel2vect and back",
     "from openalea.plantgl.light.utils import azel2vect, vect2azel\n"
     "result = [azel2vect(30, 45), azel2vect(200, 10, north=90), vect2azel(Vector3(-1,-2,-3))]", 1e-9),
    ("sky's turtle directions",
     "from openalea.plantgl.light.utils import estimate_dir_vectors\n"
     "from openalea.plantgl.light.sky import soc_sky_sources\n"
     "d = estimate_dir_vectors(soc_sky_sources(2))\n"
     "result = [len(d), d[0], d[17], d[45], sum(w for _, w in d)]", 1e-9),
    ("projection matrix and projected box",
     "from openalea.plantgl.light.utils import getProjectionMatrix, projectedBBox\n"
     "m = getProjectionMatrix(Vector3(1,1,-1), Vector3(0,0,1))\n"
     "b = projectedBBox(BoundingBox((0,0,0),(1,2,3)), Vector3(0.3,-0.2,-1), Vector3(1,0,0))\n"
     "result = [m.getRow(0), m.getRow(1), m.getRow(2), b.lowerLeftCorner, b.upperRightCorner]", 1e-9),
    ("bounding boxes",
     SPHERE_BOX + "b = BoundingBox(sc)\nc = BoundingBox(Translated((1,2,3), Cylinder(0.5, 2)))\n"
     "result = [b.lowerLeftCorner, b.upperRightCorner, b.getXRange(), b.getCenter(), c.lowerLeftCorner, c.upperRightCorner]",
     1e-9),
    ("surfaces",
     "result = [surface(Sphere(2)), surface(Box((1,2,3))), surface(Cylinder(1,2)), surface(Cylinder(1,2,False)),"
     " surface(Cone(1,3)), surface(Frustum(1,2,0.5)), surface(Disc(2)), surface(Translated((1,1,1), Sphere(1))),"
     " surface(Vector3(0,0,0), Vector3(1,0,0), Vector3(0,2,0)),"
     " surface(TriangleSet([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,2),(0,2,3)]))]", 1e-9),
    # interception
    ("directional interception from above, a square under a smaller one",
     SQUARE + "result = directionalInterception(sc, [(90, 0, 1)])", 0.02),
    ("directional interception from the side",
     SQUARE + "result = directionalInterception(sc, [(10, 30, 2)])", 0.05),
    ("diffuse interception, sphere and box",
     SPHERE_BOX + "result = diffuseInterception(sc, 1)", 1e-3),
    ("diffuse interception, a sphere above another",
     TWO_SPHERES + "result = diffuseInterception(sc, 10, screenresolution=0.05)", 1e-3),
    ("z-buffer histogram",
     SQUARE + "z = ZBufferEngine(20, 20, renderingStyle=eIdBased)\n"
     "z.setOrthographicCamera(-1, 1, -1, 1, 1, 5)\n"
     "z.lookAt(Vector3(0.5,0.5,3), Vector3(0.5,0.5,0), Vector3(0,1,0))\n"
     "z.process(sc)\nresult = dict(z.idhistogram(False))", 0),
    # PlantGL's text scene files: the same text read by both; a scene saved and read back (to
    # PlantGL's six digits: the reference writes no more)
    ("a .geom file read", DESCRIBED + GEOM_FILE + "result = described(path)", 1e-12),
    ("a scene saved as .geom and read back", DESCRIBED + SCENE_TO_SAVE + "result = described(path)", 1e-5),
    # A model's own scene: its leaves (~l) are PlantGL's turtle's leaf, turned to the turtle's
    # frame, and intercept light (the F's cylinders turn about their axis as Sprout guesses: the
    # pixels differ a little).
    ("a model's leaves in its scene, lit",
     "from openalea.lpy import Lsystem\n"
     "l = Lsystem()\nl.setCode('Axiom: F(1) +(30) /(20) ~l(2) F(1) &(50) ~l(1.5)\\n')\n"
     "sc = l.sceneInterpretation(l.axiom)\n"
     "leaves = [sh for sh in sc if type(sh.geometry.geometry.geometry).__name__ == 'Scaled']\n"
     "frames = sorted([sh.id, list(sh.geometry.translation), list(sh.geometry.geometry.primary),\n"
     "                 list(sh.geometry.geometry.secondary), list(sh.geometry.geometry.geometry.scale),\n"
     "                 [list(p) for p in sh.geometry.geometry.geometry.geometry.pointList]] for sh in leaves)\n"
     "lit = directionalInterception(sc, [(45, 30, 1), (80, 200, 1)], screenresolution=0.01)\n"
     "result = [frames, [lit[sh.id] for sh in sorted(leaves, key=lambda sh: sh.id)]]", 0.03),
]
