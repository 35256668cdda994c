# Numerics at the extremes and the statistical verification of the estimators. Included from
# tests/CMakeLists.txt, after wavetrace_test() is defined.
#
#   extremes_test            (extremes_*_test.cpp, one file per concept, extremes_helpers.h)
#                            deterministic checks at the edges of the number line and of the
#                            settings: parallel and 1-ulp rays, degenerate triangles, signed
#                            zeros, far/tiny/huge spheres, self-intersection of spawned rays,
#                            index-matched glass, Oren-Nayar at grazing view, overflow to Inf,
#                            1x1 images and idle threads. Every ISA's kernels, both layouts.
#   statistical_test         chi-square goodness of fit of every sampler, Russian roulette
#                            against none in the white furnace, and a per-pixel z-test of a
#                            low-spp wavefront render against a high-spp reference. Sized for
#                            CI (a few seconds on 2 cores).
#   statistical_long_test    the same source with WT_LONG_TESTS=1: 10-50x the samples, a
#                            larger image. Labelled `long`, so `make test` (ctest -LE long)
#                            skips it; run it with `ctest -L long`.

wavetrace_test(extremes_test extremes_triangles_test.cpp extremes_spheres_test.cpp extremes_spawned_rays_test.cpp
               extremes_glass_test.cpp extremes_oren_nayar_test.cpp extremes_film_test.cpp extremes_settings_test.cpp)
wavetrace_test(statistical_test statistical_test.cpp)

wavetrace_long_test(statistical_long_test statistical_test.cpp TIMEOUT 3600)
