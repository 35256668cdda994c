// Triangles and parallelograms at the extremes: rays parallel to a triangle and one ulp off its
// plane, degenerate and needle triangles, signed zeros, parallelogram edges and corners.

#include "extremes_helpers.h"

namespace wt::extremes {
namespace {

// ---- triangles: parallel rays and rays one ulp off the plane --------------------------------

// A point in 3D from plane coordinates (a, b) and the coordinate along the plane's normal axis.
glm::vec3 on_axis_plane(int axis, float a, float b, float normal_coordinate) {
    glm::vec3 p;
    p[axis] = normal_coordinate;
    p[(axis + 1) % 3] = a;
    p[(axis + 2) % 3] = b;
    return p;
}

TEST(TriangleParallelRays, ExactlyParallelNeverHitsAndOneUlpOffNeverGivesABadHit) {
    const float denorm_min = std::numeric_limits<float>::denorm_min();
    const float in_plane[][2] = {{1, 0}, {0, 1}, {-1, 0}, {0.6f, 0.8f}, {-0.28f, 0.96f}, {0.8f, -0.6f}};
    // Where in the plane the ray is aimed: inside, at a vertex, on an edge, outside.
    const float targets[][2] = {{0.2f, 0.3f}, {-1, -1}, {0.5f, -1}, {0.5f, 0.5f}, {3, 3}};
    for (int axis = 0; axis < 3; ++axis) {
        for (float h : {0.0f, 1.0f, -3.75f, 1000.0f, 1e-30f, 0.1f}) {
            SCOPED_TRACE("plane normal axis " + std::to_string(axis) + ", at " + hex(h));
            const Scene scene = scene_of(
                {{on_axis_plane(axis, -1, -1, h), on_axis_plane(axis, 2, -1, h), on_axis_plane(axis, -1, 2, h)}}, {});
            std::vector<Query> queries;
            for (const auto& dir : in_plane) {
                // The normal component: exactly 0 (both signs), and one ulp of zero either way.
                for (float dn : {0.0f, -0.0f, denorm_min, -denorm_min}) {
                    for (const auto& target : targets) {
                        // The origin: in the plane and one ulp above and below it.
                        for (float oh : {h, std::nextafter(h, kInf), std::nextafter(h, -kInf)}) {
                            const glm::vec3 d = on_axis_plane(axis, dir[0], dir[1], dn);
                            const glm::vec3 o = on_axis_plane(axis, target[0] - 2.5f * dir[0], target[1] - 2.5f * dir[1], oh);
                            queries.push_back({{o, d}});
                        }
                    }
                }
            }
            expect_everywhere(scene, queries, [&](std::size_t, const Query& q, const Answer& a) -> std::string {
                if (q.ray.direction[axis] == 0.0f && a.found()) return "a ray parallel to the plane hit the triangle";
                return "";  // one ulp off: anything is fine that passes the sanity check (finite, positive t)
            });
        }
    }
}

TEST(TriangleParallelRays, TiltedPlaneExactlyParallelAndOneUlpOff) {
    // The plane x = z. The direction (s, 0, s) is exactly parallel in float too: the triple
    // product cancels exactly. Then s +- 1 ulp in z, and the origin +- 1 ulp off the plane.
    const Scene scene = scene_of({{glm::vec3(0, -1, 0), glm::vec3(2, -1, 2), glm::vec3(0, 2, 0)}}, {});
    const float s = std::sqrt(0.5f);
    std::vector<Query> queries;
    std::vector<bool> parallel;
    for (float dz : {s, std::nextafter(s, 2.0f), std::nextafter(s, 0.0f)}) {
        for (float dy : {0.0f, -0.0f}) {
            for (float start : {-1.0f, -0.25f, 0.3f}) {
                for (float y : {-0.5f, 0.0f, 0.25f}) {
                    const float x = start;
                    for (float z : {x, std::nextafter(x, kInf), std::nextafter(x, -kInf)}) {
                        queries.push_back({{{x, y, z}, {s, dy, dz}}});
                        parallel.push_back(dz == s);
                    }
                }
            }
        }
    }
    expect_everywhere(scene, queries, [&](std::size_t i, const Query&, const Answer& a) -> std::string {
        if (parallel[i] && a.found()) return "a ray parallel to the plane hit the triangle";
        return "";
    });
}

// ---- degenerate triangles -------------------------------------------------------------------

struct Degenerate {
    const char* name;
    std::array<glm::vec3, 3> v;
};

// Zero area in exact arithmetic: the three vertices are one point or on one line, and every
// coordinate is an integer (or a dyadic), so the float vertices are exactly what is written.
const Degenerate kZeroArea[] = {
    {"point", {glm::vec3(0.25f, 0.5f, 0.75f), glm::vec3(0.25f, 0.5f, 0.75f), glm::vec3(0.25f, 0.5f, 0.75f)}},
    {"collinear_on_axis", {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(2, 0, 0)}},
    {"collinear_repeated_vertex", {glm::vec3(0, 0, 0), glm::vec3(0, 0, 0), glm::vec3(1, 1, 1)}},
    {"collinear_middle_vertex_last", {glm::vec3(0, 0, 0), glm::vec3(2, 0, 0), glm::vec3(1, 0, 0)}},
    {"collinear_generic_1", {glm::vec3(1, 2, 3), glm::vec3(3, 5, 4), glm::vec3(7, 11, 6)}},
    {"collinear_generic_2", {glm::vec3(0, 0, 0), glm::vec3(1, 2, 3), glm::vec3(3, 6, 9)}},
    {"collinear_generic_3", {glm::vec3(-2, 1, 0.5f), glm::vec3(-1, 1.5f, 1.25f), glm::vec3(2, 3, 3.5f)}},
};

// Rays that cross the degenerate triangle's segment (through its vertices, midpoints and
// other points of it) from random directions, and random rays that pass anywhere.
std::vector<Query> rays_at_segment(const std::array<glm::vec3, 3>& v, int count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Query> queries;
    // The segment's end points: the two vertices farthest apart.
    glm::vec3 a = v[0], b = v[1];
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (glm::length(v[i] - v[j]) > glm::length(b - a)) a = v[i], b = v[j];
    for (int i = 0; i < count; ++i) {
        const float s = (i % 4 == 0) ? float(i % 3) * 0.5f : u01(rng);  // vertices and midpoint, then anywhere
        const glm::vec3 target = a + s * (b - a);
        const glm::vec3 d = random_unit(rng);
        const float distance = 0.01f + 5.0f * u01(rng);
        queries.push_back({{target - distance * d, d}});
    }
    // Along the segment's own line, from outside it.
    if (glm::length(b - a) > 0.0f) {
        const glm::vec3 along = glm::normalize(b - a);
        queries.push_back({{a - along, along}});
        queries.push_back({{b + along, -along}});
    }
    // Random rays in a box around the triangle.
    for (int i = 0; i < count; ++i) {
        const glm::vec3 o = a + glm::vec3(8.0f * u01(rng) - 4.0f, 8.0f * u01(rng) - 4.0f, 8.0f * u01(rng) - 4.0f);
        queries.push_back({{o, random_unit(rng)}});
    }
    return queries;
}

// Distance in double from the point p to the segment [a, b].
double point_segment_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double s = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

// Distance in double from the line o + t d to the segment [a, b]: the closest point of the
// infinite lines, its segment parameter clamped to [0, 1] (the distance is convex along it).
double line_segment_distance(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a, w = a - o;
    const double A = glm::dot(ab, ab), B = glm::dot(ab, d), C = glm::dot(d, d), D = glm::dot(ab, w), E = glm::dot(d, w);
    const double denominator = A * C - B * B;
    const double s = denominator > 1e-300 ? std::clamp((B * E - C * D) / denominator, 0.0, 1.0) : 0.0;
    const glm::dvec3 f = a + s * ab - o;
    return glm::length(f - (glm::dot(f, d) / C) * d);
}

AccuracySettings watertight_triangles() {
    AccuracySettings a;
    a.triangles = TriangleTest::watertight;
    return a;
}

// The parameter t where the line o + t d comes closest to the segment [a, b] (double).
double line_segment_closest_t(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a, w = a - o;
    const double A = glm::dot(ab, ab), B = glm::dot(ab, d), C = glm::dot(d, d), D = glm::dot(ab, w), E = glm::dot(d, w);
    const double denominator = A * C - B * B;
    const double s = denominator > 1e-300 ? std::clamp((B * E - C * D) / denominator, 0.0, 1.0) : 0.0;
    return glm::dot(a + s * ab - o, d) / C;
}

// Zero-area triangles: a ray whose line passes more than 1e-5 from the segment (or point)
// must never hit it; with `even_crossing`, neither may a ray that crosses it exactly.
void expect_zero_area_never_hit(const std::vector<Degenerate>& triangles, uint32_t seed, bool even_crossing,
                                const AccuracySettings& accuracy = {}) {
    for (const Degenerate& tri : triangles) {
        SCOPED_TRACE(tri.name);
        Scene scene = scene_of({tri.v}, {});
        scene.settings.accuracy = accuracy;
        const glm::dvec3 a(tri.v[0]), b(tri.v[1]), c(tri.v[2]);
        expect_everywhere(scene, rays_at_segment(tri.v, 4000, seed), [&](std::size_t, const Query& q, const Answer& hit) -> std::string {
            if (!hit.found()) return "";
            const glm::dvec3 o(q.ray.origin), d(q.ray.direction);
            double distance = std::numeric_limits<double>::infinity(), crossing_t = 0.0;
            for (const auto& [p, r] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
                const double e = line_segment_distance(o, d, p, r);
                if (e < distance) distance = e, crossing_t = line_segment_closest_t(o, d, p, r);
            }
            if (distance > 1e-5) return "false hit on a triangle of zero area: the ray passes " + std::to_string(distance) + " from it";
            if (!even_crossing) return "";
            return "hit a triangle of zero area; the ray crosses its segment at t = " + std::to_string(crossing_t);
        });
    }
}

// FOUND: generic (not axis-aligned) zero-area triangles were hit by 10-20% of the rays crossing
// their segment, at wrong distances: det = e1 . (d x e2) is zero in exact arithmetic but a few
// ulps in float, so u, v and t were ratios of rounding errors. Reproduction (before the fix):
//   TriangleSoA t; t.push_back({0,0,0}, {1,2,3}, {3,6,9}, 0);
//   Ray r{{-0x1.c4577p-3f, -0x1.492694p+1f, 0x1.df6198p-1f}, {0x1.cf2db8p-3f, 0x1.d53d1p-1f, 0x1.51f084p-2f}};
//   intersect_triangle returned true with t = 4 (the ray crosses the segment at t = 4.588).
// Fixed: TriangleSoA collapses slivers (is_sliver, geometry_soa.h) so no kernel can hit them.
TEST(DegenerateTriangles, ZeroAreaTrianglesAreNeverHit) {
    expect_zero_area_never_hit({std::begin(kZeroArea), std::end(kZeroArea)}, 11, true);
}

// FOUND in the watertight option as well (edge functions of rounding noise, det != 0); the same fix.
TEST(DegenerateTriangles, ZeroAreaTrianglesAreNeverHitWithTheWatertightOption) {
    expect_zero_area_never_hit({std::begin(kZeroArea), std::end(kZeroArea)}, 11, true, watertight_triangles());
}

TEST(DegenerateTriangles, ZeroAreaTrianglesAreNeverHitByRaysThatPassClearOfThem) {
    expect_zero_area_never_hit({std::begin(kZeroArea), std::end(kZeroArea)}, 14, false);
}

// What does hold by default: the cross product of an axis-aligned degenerate triangle's edges
// rounds to exactly zero, det is exactly zero, and the det == 0 rejection works; and for every
// zero-area triangle, no NaN, no infinite or negative distance, any-hit agreeing with closest.
TEST(DegenerateTriangles, AxisAlignedZeroAreaTrianglesAreNeverHit) {
    expect_zero_area_never_hit({kZeroArea[0], kZeroArea[1], kZeroArea[2], kZeroArea[3]}, 12, true);
}

TEST(DegenerateTriangles, ZeroAreaTrianglesNeverGiveNaNOrABadDistance) {
    for (const Degenerate& tri : kZeroArea) {
        SCOPED_TRACE(tri.name);
        const Scene scene = scene_of({tri.v}, {});
        expect_everywhere(scene, rays_at_segment(tri.v, 4000, 11), [](std::size_t, const Query&, const Answer&) { return ""; });
    }
}

// Needles: real triangles with one edge 1e-7 the length of the others. A ray whose line passes
// more than 1e-5 from the needle must miss it; a hit must report a point (o + t d) within 1e-5
// of the needle; and no NaN.
void expect_needles_give_no_false_hit(const std::vector<std::array<glm::vec3, 3>>& needles, const AccuracySettings& accuracy = {}) {
    for (const auto& v : needles) {
        SCOPED_TRACE("needle " + hex(v[0]) + " " + hex(v[1]) + " " + hex(v[2]));
        Scene scene = scene_of({v}, {});
        scene.settings.accuracy = accuracy;
        const glm::dvec3 a(v[0]), b(v[1]), c(v[2]);
        expect_everywhere(scene, rays_at_segment(v, 4000, 13), [&](std::size_t, const Query& q, const Answer& hit) -> std::string {
            if (!hit.found()) return "";
            const glm::dvec3 o(q.ray.origin), d(q.ray.direction);
            const double line_distance = std::min({line_segment_distance(o, d, a, b), line_segment_distance(o, d, b, c),
                                                   line_segment_distance(o, d, c, a)});
            if (line_distance > 1e-5) return "false hit: the ray passes " + std::to_string(line_distance) + " from the needle";
            const glm::dvec3 p = o + double(hit.t) * d;
            const double point_distance = std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                                                    point_segment_distance(p, c, a)});
            if (point_distance > 1e-5)
                return "hit at the wrong distance: the point o + t d is " + std::to_string(point_distance) + " from the needle";
            return "";
        });
    }
}

const std::vector<std::array<glm::vec3, 3>> kAxisPlaneNeedles = {
    {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(1, 1e-7f, 0)},    // short edge v1-v2, in z = 0
    {glm::vec3(0, 0, 0), glm::vec3(1e-7f, 0, 0), glm::vec3(0.5f, 1, 0)},  // short edge v0-v1
    {glm::vec3(0.5f, 0.5f, 0.5f), glm::vec3(0.5f, 0.5f, 0.5f + 1e-7f), glm::vec3(-0.5f, 0.5f, -0.25f)},  // in y = 0.5
};
const std::vector<std::array<glm::vec3, 3>> kTiltedNeedles = {
    {glm::vec3(0, 0, 0), glm::vec3(0.6f, 0.8f, 0), glm::vec3(0.6f, 0.8f, 1e-7f)},
    {glm::vec3(0.1f, 0.2f, 0.3f), glm::vec3(0.7f, -0.2f, 0.9f), glm::vec3(0.7f, -0.2f + 1e-7f, 0.9f)},
};

TEST(DegenerateTriangles, NeedlesInAxisPlanesGiveNoFalseHit) { expect_needles_give_no_false_hit(kAxisPlaneNeedles); }

// FOUND: a needle whose plane is not an axis plane was hit at the wrong distance by about 40%
// of the rays crossing it (det cancels from ~0.5 to ~1e-7, below its own rounding error):
//   TriangleSoA t; t.push_back({0,0,0}, {0.6f,0.8f,0}, {0.6f,0.8f,1e-7f}, 0);
//   Ray r{{0x1.f19b0ep-1f, -0x1.cb453ep-1f, 0x1.0c5994p+1f}, {-0x1.3107f2p-3f, 0x1.39db0ep-1f, -0x1.8d4516p-1f}};
//   gave t = 4.4148 where the ray crosses at t = 2.7019. Fixed with the slivers above.
TEST(DegenerateTriangles, TiltedNeedlesGiveNoFalseHit) { expect_needles_give_no_false_hit(kTiltedNeedles); }

// FOUND in the watertight option too (t off by up to 0.04); the same fix.
TEST(DegenerateTriangles, TiltedNeedlesGiveNoFalseHitWithTheWatertightOption) {
    expect_needles_give_no_false_hit(kTiltedNeedles, watertight_triangles());
}

// ---- signed zeros ---------------------------------------------------------------------------

// Every zero component of the direction as -0 instead of +0 must not change anything: same
// primitive, same t, u and v (as numbers), same any-hit answer.
// ---- parallelograms: edges, corners and the diagonal a triangle pair would have -------------

// Two skewed parallelograms sharing an edge, hit through their corners, their edge points, one
// float step inside and outside their far edges and the diagonal where a triangle split would
// put its seam, and by rays parallel to their plane. Every implementation must give the scalar
// functions' bits, a parallelogram's (u, v) stays in the unit square, and a ray aimed well
// inside (or well outside) must hit (or miss).
TEST(ParallelogramExtremes, EdgesCornersAndTheDiagonalOnEveryImplementation) {
    const glm::vec3 v0(0.1f, 0.2f, 0.3f), e1(1.3f, 0.2f, -0.1f), e2(-0.2f, 0.9f, 0.4f);
    Scene scene = scene_of({}, {});
    scene.triangles.push_parallelogram(v0, v0 + e1, v0 + e2, 0);
    scene.triangles.push_parallelogram(v0 + e1, v0 + e1 + e1, v0 + e1 + e2, 0);  // shares the edge v0 + e1 .. + e2
    const glm::vec3 normal = glm::normalize(glm::cross(e1, e2));
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    std::vector<Query> queries;
    std::vector<int> expect;  // 1: must hit, 0: must miss, -1: either (on or within a step of a boundary)
    const float below = std::nextafter(1.0f, 0.0f), above = std::nextafter(1.0f, 2.0f);
    const float params[] = {0.0f, 0.5f, 1.0f, below, above, -0x1p-24f, 0x1p-24f, 0.25f, 0.75f};
    for (float a : params) {
        for (float b : params) {
            for (float s : {0.0f, 1.0f}) {  // the first parallelogram, or the second one along e1
                const glm::vec3 target = v0 + (a + s) * e1 + b * e2;
                const bool inside_far = a > 0.01f && a < 0.99f && b > 0.01f && b < 0.99f;
                for (int k = 0; k < 6; ++k) {
                    glm::vec3 d = random_unit(rng);
                    if (std::fabs(glm::dot(d, normal)) < 0.05f) d = glm::normalize(d + normal);
                    queries.push_back({{target - (0.5f + 3.0f * u01(rng)) * d, d}});
                    expect.push_back(inside_far ? 1 : -1);
                }
            }
        }
    }
    // Clearly outside both, and parallel to the plane through the middle.
    for (int k = 0; k < 200; ++k) {
        const glm::vec3 d = random_unit(rng);
        if (std::fabs(glm::dot(d, normal)) < 0.05f) continue;
        const glm::vec3 target = v0 + (u01(rng) < 0.5f ? -0.2f - u01(rng) : 2.2f + u01(rng)) * e1 + (u01(rng) * 3.0f - 1.0f) * e2;
        queries.push_back({{target - 2.0f * d, d}});
        expect.push_back(0);
    }
    const glm::vec3 in_plane = glm::normalize(e1 - glm::dot(e1, normal) * normal);
    queries.push_back({{v0 + 0.5f * e2 - in_plane, in_plane}});
    expect.push_back(-1);  // exactly parallel only up to rounding of the normal: either, if sane

    std::vector<Answer> scalar;
    for (const Query& q : queries) scalar.push_back(scalar_answer(scene, q));
    auto same_bits = [](float x, float y) { return std::memcmp(&x, &y, sizeof x) == 0; };
    expect_everywhere(scene, queries, [&](std::size_t i, const Query&, const Answer& a) -> std::string {
        const Answer& s = scalar[i];
        if (a.prim != s.prim || !same_bits(a.t, s.t) || (a.found() && (!same_bits(a.u, s.u) || !same_bits(a.v, s.v))))
            return "differs from the scalar functions: " + describe(s);
        if (expect[i] == 1 && !a.found()) return "missed a point well inside";
        if (expect[i] == 0 && a.found()) return "hit a point well outside";
        return "";
    });
}

TEST(SignedZeroDirections, NegativeZeroBehavesLikePositiveZero) {
    const Scene hexroom = build_scene(test::hexroom(8, 8, 1));
    const Scene triangle = scene_of({{glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)}}, {{glm::vec3(0, 0, 3), 0.5f}});
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u01(0.0f, 1.0f);
    // Directions with one or two zero components.
    std::vector<glm::vec3> directions = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0},
                                         {0.6f, 0, 0.8f}, {0, -0.8f, 0.6f}, {-0.28f, 0.96f, 0}};
    // Origins: random, and exactly above the triangle's vertices, edges and interior, and on
    // the line through the sphere's centre and its silhouette.
    std::vector<glm::vec3> origins = {{0, 0, 2},  {1, 0, 2},    {0, 1, 2},     {0.5f, 0.5f, 2}, {0.5f, 0, 2},
                                      {0, 0.5f, 2}, {0.25f, 0.25f, -2}, {0, 0, 5}, {0.5f, 0, 5}, {0, 0.5f, 1},
                                      {-1, 0, 0}, {-1, 0.5f, 0}, {0, -1, 0}, {0.5f, -1, 0}};
    for (int i = 0; i < 200; ++i) origins.push_back({u01(rng) * 14 - 2.5f, u01(rng) * 10 - 5, u01(rng) * 9.8f - 4.9f});
    for (const Scene* scene : {&triangle, &hexroom}) {
        SCOPED_TRACE(scene == &hexroom ? "hexroom" : "unit triangle and sphere");
        std::vector<Query> queries;
        std::vector<std::size_t> positive_zero_twin;  // index of the all-+0 version of each query
        for (const glm::vec3& o : origins) {
            for (const glm::vec3& d : directions) {
                const std::size_t base = queries.size();
                // Every combination of signs of the zero components.
                for (int mask = 0; mask < 8; ++mask) {
                    glm::vec3 signed_d = d;
                    bool valid = true;
                    for (int k = 0; k < 3; ++k) {
                        if ((mask >> k) & 1) {
                            if (d[k] != 0.0f) valid = false;
                            signed_d[k] = -0.0f;
                        }
                    }
                    if (!valid) continue;
                    queries.push_back({{o, signed_d}});
                    positive_zero_twin.push_back(base);
                }
            }
        }
        for (const ImplementationRun& run : intersect_everywhere(*scene, queries)) {
            Failures failures;
            for (std::size_t i = 0; i < queries.size(); ++i) {
                const Answer& a = run.answers[i];
                const Answer& b = run.answers[positive_zero_twin[i]];
                const std::string problem = sanity_problem(*scene, queries[i], a);
                if (!problem.empty()) {
                    failures.add(run.implementation + ": " + problem + "\n  " + describe(queries[i].ray) + "\n  got " + describe(a));
                } else if (a.prim != b.prim || a.t != b.t || a.u != b.u || a.v != b.v || a.occluded != b.occluded) {
                    failures.add(run.implementation + ": -0 and +0 differ\n  " + describe(queries[i].ray) + "\n  got " +
                                 describe(a) + "\n  with +0: " + describe(queries[positive_zero_twin[i]].ray) + "\n  got " +
                                 describe(b));
                }
            }
        }
    }
}


}  // namespace
}  // namespace wt::extremes
