// What a scene's TriangleSoA stores: each mesh vertex once and three indices and a material per
// triangle, whichever the test; the edges, normals and corners the tests read are derived from
// them. A scene built for one test and then asked to run the other is refused with a message.
// The flat kernels' rows (triangle_rows.h) are copies of exactly what the accessors return.

#include <algorithm>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/scene/scene.h"
#include "kernels/isa/intersect_dispatch.h"
#include "kernels/primitives/triangle_rows.h"
#include "kernels/renderer.h"
#include "bvh_test_scenes.h"

namespace wt {
namespace {

// The hexroom with its meshes, every quad split into two triangles, so that a scene built for
// Moller-Trumbore has no parallelogram (which alone would make the watertight test refuse it).
SceneDescription hexroom_of_triangles(TriangleTest test) {
    SceneDescription d = test::hexroom_with_meshes(4, 4, 1);
    for (TriangleMesh& m : d.meshes) m.parallelogram = false;
    d.settings.accuracy.triangles = test;
    return d;
}

TEST(TriangleStorage, ASceneStoresEachMeshVertexOnce) {
    const SceneDescription d = hexroom_of_triangles(TriangleTest::moller_trumbore);
    const Scene mt = build_scene(d);
    const Scene wt = build_scene(hexroom_of_triangles(TriangleTest::watertight));
    ASSERT_GT(mt.triangles.size(), 2000u);
    ASSERT_EQ(wt.triangles.size(), mt.triangles.size());
    std::size_t vertices = 0, triangles = 0;
    for (const TriangleMesh& m : d.meshes) vertices += m.vertices.size(), triangles += m.triangles.size();
    ASSERT_EQ(mt.triangles.size(), triangles);
    ASSERT_LT(vertices, triangles);  // the meshes share vertices between triangles
    for (const Scene* s : {&mt, &wt}) {
        EXPECT_EQ(s->triangles.vertex_count(), vertices);
        EXPECT_EQ(s->triangles.bytes(), vertices * 3 * sizeof(float) + triangles * 4 * sizeof(uint32_t));
    }

    EXPECT_TRUE(mt.triangles.has_scaled_normal());
    EXPECT_FALSE(mt.triangles.has_vertices());
    EXPECT_TRUE(wt.triangles.has_vertices());
    EXPECT_FALSE(wt.triangles.has_scaled_normal());

    // A TriangleSoA of its own (tests, benchmarks) serves both tests.
    TriangleSoA both;
    both.push_back({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0);
    EXPECT_TRUE(both.serves(TriangleTest::moller_trumbore) && both.serves(TriangleTest::watertight));
    EXPECT_FALSE(mt.triangles.serves(TriangleTest::watertight));
    EXPECT_FALSE(wt.triangles.serves(TriangleTest::moller_trumbore));
    EXPECT_THROW(both.store_only_for(TriangleTest::watertight), std::logic_error);
}

TEST(TriangleStorage, NormalsAndVerticesAreWhatTheTestSees) {
    const SceneDescription d = hexroom_of_triangles(TriangleTest::moller_trumbore);
    const Scene mt = build_scene(d);
    const Scene wt = build_scene(hexroom_of_triangles(TriangleTest::watertight));
    std::size_t i = 0, slivers = 0;
    for (const TriangleMesh& m : d.meshes)
        for (const auto& tri : m.triangles) {
            const glm::vec3 a = m.vertices[tri[0]], b = m.vertices[tri[1]], c = m.vertices[tri[2]];
            SCOPED_TRACE("triangle " + std::to_string(i));
            ASSERT_EQ(mt.triangles.vertex0(i), wt.triangles.vertex0(i));
            const glm::vec3 n = mt.triangles.normal(i);
            if (is_sliver(a, b, c)) {
                EXPECT_EQ(n, glm::vec3(0.0f));  // stored collapsed: no direction
                ++slivers;
            } else {
                // The unit normal of the given corners, to the rounding of the edges.
                const glm::vec3 expected = glm::normalize(glm::cross(b - a, c - a));
                EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
                EXPECT_GT(glm::dot(n, expected), 1.0f - 1e-5f);
                // The watertight scene keeps the corners as given; Moller-Trumbore's are v0 + e.
                EXPECT_EQ(wt.triangles.vertex1(i), b);
                EXPECT_EQ(wt.triangles.vertex2(i), c);
                EXPECT_EQ(mt.triangles.vertex1(i), mt.triangles.vertex0(i) + mt.triangles.edge1(i));
                EXPECT_EQ(mt.triangles.vertex2(i), mt.triangles.vertex0(i) + mt.triangles.edge2(i));
            }
            EXPECT_EQ(wt.triangles.normal(i), n);  // the same edges, the same bits
            ++i;
        }
    EXPECT_EQ(i, mt.triangles.size());
    EXPECT_LT(slivers, i / 100);
}

TEST(TriangleStorage, TheOtherTestIsRefusedNotReadOutOfBounds) {
    for (TriangleTest built : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        SCOPED_TRACE(std::string("built for ") + name_of(built));
        Scene scene = build_scene(hexroom_of_triangles(built));
        ASSERT_EQ(scene.triangles.parallelogram_count, 0u);
        EXPECT_NO_THROW(FlatScene(scene).view());
        scene.settings.accuracy.triangles =
            built == TriangleTest::moller_trumbore ? TriangleTest::watertight : TriangleTest::moller_trumbore;
        try {
            Film film(4, 4);
            render(scene, RenderOptions{}, film);
            ADD_FAILURE() << "render accepted triangles stored for another test";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("stored for another triangle test"), std::string::npos) << e.what();
        }
        EXPECT_THROW(FlatScene(scene).view(), std::invalid_argument);
    }
}

// The rows the flat kernels and a BVH's beside list read: the first n entries, bit for bit what
// the scene's accessors return, only the rows of the scene's test, and its parallelograms.
TEST(TriangleStorage, RowsCopyTheLeadingEntriesBitForBit) {
    for (TriangleTest test : {TriangleTest::moller_trumbore, TriangleTest::watertight}) {
        SCOPED_TRACE(std::string("stored for ") + name_of(test));
        SceneDescription d = test::hexroom_with_meshes(4, 4, 1);
        d.settings.accuracy.triangles = test;
        const Scene scene = build_scene(d);
        const TriangleSoA& t = scene.triangles;
        ASSERT_EQ(t.parallelogram_count > 0, test == TriangleTest::moller_trumbore);
        for (const std::size_t n : {std::size_t(t.parallelogram_count), std::size_t(t.parallelogram_count) + 2, t.size()}) {
            const TriangleRows rows = triangle_rows(t, n);
            ASSERT_EQ(rows.count, n);
            EXPECT_EQ(rows.parallelogram_count, t.parallelogram_count);
            const bool mt = test == TriangleTest::moller_trumbore;
            EXPECT_EQ(rows.scaled_nx.size(), mt ? n : 0u);
            EXPECT_EQ(rows.v1x.size(), mt ? 0u : n);
            const auto at = [](const AlignedVector<float>& x, const AlignedVector<float>& y, const AlignedVector<float>& z,
                               std::size_t i) { return glm::vec3(x[i], y[i], z[i]); };
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(at(rows.v0x, rows.v0y, rows.v0z, i), t.vertex0(i)) << i;
                ASSERT_EQ(at(rows.e1x, rows.e1y, rows.e1z, i), t.edge1(i)) << i;
                ASSERT_EQ(at(rows.e2x, rows.e2y, rows.e2z, i), t.edge2(i)) << i;
                if (mt) {
                    ASSERT_EQ(at(rows.scaled_nx, rows.scaled_ny, rows.scaled_nz, i), t.scaled_normal(i)) << i;
                } else {
                    ASSERT_EQ(at(rows.v1x, rows.v1y, rows.v1z, i), t.vertex1(i)) << i;
                    ASSERT_EQ(at(rows.v2x, rows.v2y, rows.v2z, i), t.vertex2(i)) << i;
                }
            }
        }
        EXPECT_EQ(triangle_rows(t, 1).parallelogram_count, std::min(1u, t.parallelogram_count));
        EXPECT_THROW(triangle_rows(t, t.size() + 1), std::logic_error);
    }
}

// Vertices added a few at a time (a triangle or a small mesh per call) grow the arrays
// geometrically: reserving exactly what each call adds reallocated on every call, which made a
// scene of many small meshes quadratic to build.
TEST(TriangleStorage, VerticesAddedAFewAtATimeReallocateLogarithmicallyOften) {
    TriangleSoA t;
    std::size_t reallocations = 0, capacity = t.px.capacity();
    for (int i = 0; i < 10000; ++i) {
        t.push_back({float(i), 0, 0}, {float(i) + 1, 0, 0}, {float(i), 1, 0}, 0);
        if (t.px.capacity() != capacity) ++reallocations, capacity = t.px.capacity();
    }
    EXPECT_EQ(t.vertex_count(), 30000u);
    EXPECT_LE(reallocations, 40u);
    EXPECT_GE(reallocations, 1u);
}


// A scene's meshes are reserved for before they are added (TriangleSoA::reserve_for): its arrays
// are allocated once, and then hold exactly the meshes' vertices and triangles. Without the
// reservation the same scene's arrays move as they grow (asserted too, so the test shows the
// difference it guards).
TEST(TriangleStorage, ASceneReservesItsMeshesBeforeAddingThem) {
    SceneDescription d = test::hexroom_with_meshes(40, 40, 1);
    std::size_t vertices = 0, triangles = 0;
    for (const TriangleMesh& m : d.meshes) vertices += m.vertices.size(), triangles += m.triangles.size();
    ASSERT_GT(triangles, 1000u);
    const auto fill = [&](TriangleSoA& t, bool reserve) {
        if (reserve) t.reserve_for(d.meshes);
        const float* px = t.px.data();
        const uint32_t* i0 = t.i0.data();
        std::size_t moves = 0;
        for (const TriangleMesh& m : d.meshes) {
            const uint32_t first = t.add_vertices(m.vertices);
            for (const auto& tri : m.triangles) t.push(first + tri[0], first + tri[1], first + tri[2], m.material);
            moves += (t.px.data() != px) + (t.i0.data() != i0);
            px = t.px.data(), i0 = t.i0.data();
        }
        return moves;
    };
    TriangleSoA reserved, grown;
    EXPECT_EQ(fill(reserved, true), 0u);
    EXPECT_GT(fill(grown, false), 0u);
    EXPECT_EQ(reserved.vertex_count(), vertices);
    EXPECT_EQ(reserved.size(), triangles);
    EXPECT_EQ(reserved.px.capacity(), vertices);
    EXPECT_EQ(reserved.material.capacity(), triangles);
    EXPECT_EQ(reserved.i2, grown.i2);

    // build_scene reserves the same way (a quad stored as one parallelogram leaves room unused).
    const Scene scene = build_scene(d);
    EXPECT_EQ(scene.triangles.px.capacity(), scene.triangles.vertex_count());
    EXPECT_GE(scene.triangles.i0.capacity(), scene.triangles.size());
    EXPECT_LE(scene.triangles.i0.capacity(), triangles);
}
// A sliver is stored with all three indices on its first vertex, so its edges are exactly zero.
TEST(TriangleStorage, ASliverCollapsesOntoItsFirstVertex) {
    TriangleSoA t;
    const uint32_t first = t.add_vertices({{0, 0, 0}, {1, 0, 0}, {2, 1e-9f, 0}, {0, 1, 0}});
    t.push(first, first + 1, first + 2, 0);  // collinear to float precision
    t.push(first, first + 1, first + 3, 0);
    EXPECT_EQ(t.i1[0], first);
    EXPECT_EQ(t.i2[0], first);
    EXPECT_EQ(t.edge1(0), glm::vec3(0.0f));
    EXPECT_EQ(t.edge2(0), glm::vec3(0.0f));
    EXPECT_EQ(t.normal(0), glm::vec3(0.0f));
    EXPECT_EQ(t.edge1(1), glm::vec3(1, 0, 0));
    EXPECT_EQ(t.edge2(1), glm::vec3(0, 1, 0));
    EXPECT_EQ(t.normal(1), glm::vec3(0, 0, 1));
    EXPECT_EQ(t.vertex_count(), 4u);
}

}  // namespace
}  // namespace wt
