// Radiance overflowing to infinity: dropped, counted, never written.

#include "extremes_helpers.h"

namespace wt::extremes {
namespace {

// ---- film: radiance that overflows to infinity ----------------------------------------------

// A floor under a light of emission 3e38 (a float step from overflow): the light seen directly
// is finite (though beyond the film's range), and next-event estimation multiplies it by
// f * G > 1 below the light, so the sample overflows to +inf. Those samples must be dropped
// and counted, and the image finite.
SceneDescription overflowing_scene() {
    SceneDescription d;
    Material floor, light;
    floor.name = "floor";
    floor.albedo = glm::vec3(0.8f);
    light.name = "light";
    light.emission = glm::vec3(3e38f);
    d.materials = {floor, light};
    TriangleMesh floor_mesh, light_mesh;
    floor_mesh.vertices = {{-3, -3, 0}, {3, -3, 0}, {3, 3, 0}, {-3, 3, 0}};  // normal +z
    floor_mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    light_mesh.vertices = {{-1, -1, 0.5f}, {-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f}};  // normal -z
    light_mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    light_mesh.material = 1;
    d.meshes = {floor_mesh, light_mesh};
    d.camera.eye = glm::vec3(0, -3, 0.25f);
    d.camera.look_at = glm::vec3(0, 0, 0.1f);
    d.camera.fov_degrees = 80.0f;
    d.settings.width = 12;
    d.settings.height = 10;
    // About 1 sample in 450 overflows; at 8 spp (960 samples) one random stream in eight had
    // none, so the test held only for the random numbers it was written with. 64 spp: ~17.
    d.settings.spp = 64;
    d.settings.shadow_rays = 2;
    return d;
}

TEST(FilmOverflow, InfiniteSamplesAreCountedAndTheImageStaysFinite) {
    const SceneDescription d = overflowing_scene();
    const int pixels = d.settings.width * d.settings.height;
    std::vector<test::RenderedFilm> films;
    struct Variant {
        Integrator integrator;
        Isa isa;
    };
    std::vector<Variant> variants = {{Integrator::reference, Isa::scalar}};
    for (Isa isa : supported_isas()) variants.push_back({Integrator::wavefront, isa});
    for (const Variant& v : variants) {
        SCOPED_TRACE(v.integrator == Integrator::reference ? "reference" : std::string("wavefront, ") + isa_name(v.isa));
        test::RenderedFilm r = test::render_film(d, v.integrator, 2, 16, 2048, v.isa);
        const RayCounts& c = r.result.counts;
        EXPECT_GT(c.nonfinite_samples, 0u) << "the scene was meant to overflow";
        EXPECT_LT(c.nonfinite_samples, c.samples) << "and not everywhere";
        EXPECT_EQ(c.samples, uint64_t(pixels) * uint64_t(d.settings.spp));
        uint64_t kept = 0;
        for (uint32_t p = 0; p < uint32_t(pixels); ++p) kept += r.film.pixel_count(p);
        EXPECT_EQ(kept + c.nonfinite_samples, c.samples) << "every sample either kept or counted as dropped";
        const std::vector<float> rgb = r.film.resolve();
        ASSERT_EQ(rgb.size(), std::size_t(3 * pixels));
        for (std::size_t i = 0; i < rgb.size(); ++i) {
            ASSERT_TRUE(std::isfinite(rgb[i])) << "resolved value " << i << " is " << rgb[i];
            ASSERT_GE(rgb[i], 0.0f);
            // The film's exact sums hold samples below 2^43 (their squares below 2^86): the
            // light seen directly is finite in float but beyond that, and dropped too.
            ASSERT_LT(rgb[i], 0x1p43f) << "resolved value " << i;
        }
        for (uint32_t p = 0; p < uint32_t(pixels); ++p) {
            const glm::dvec3 v = r.film.pixel_sample_variance(p);
            EXPECT_FALSE(std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z)) << "pixel " << p;
        }
        films.push_back(std::move(r));
    }
    // Both integrators and every ISA drop the same samples: same bits, same counts.
    for (std::size_t i = 1; i < films.size(); ++i) {
        EXPECT_TRUE(test::films_bit_identical(films[0].film, films[i].film)) << "variant " << i;
        EXPECT_EQ(films[0].result.counts.nonfinite_samples, films[i].result.counts.nonfinite_samples) << "variant " << i;
    }
}


}  // namespace
}  // namespace wt::extremes
