// Which per-pixel error should adaptive sampling stop on? An experiment (README, "Adaptive
// sampling"): every sample of every pixel of a scene is traced once (the reference integrator,
// the renderer's bits), then the stopping rule (decision points, 3x3 dilation, final stops:
// kernels/adaptive/) is replayed on those samples with two error estimates:
//
//   se:   the standard error of the mean from the sums of squares (kernels/adaptive/pixel_error.h)
//   half: Cycles' |image - image of the even samples| (Dammertz et al. 2010, sec. 2.1)
//
// each over a ladder of thresholds, and for uniform sampling at each spp of the ladder. Every
// row: the mean spp spent and the error of the image against a reference. An estimate is better
// when its rows reach a lower error for the same mean spp.
//
//   adaptive_estimators SCENE REFERENCE.exr WIDTH HEIGHT MAX_SPP MIN_SPP,... [THREADS]   the table (CSV, stdout)
//   adaptive_estimators film-cost EXTRA_CHANNELS    1M samples into a 64x64 film (callgrind: the cost
//                                                   of the half image's 3 extra channels per sample)
//   adaptive_estimators rule-cost SCENE             the stopping rule once over a 200x200 film of 16 spp
//                                                   (callgrind: its cost per pixel)
// The cost modes count only between the CALLGRIND_TOGGLE_COLLECT marks (--collect-atstart=no).

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <valgrind/callgrind.h>

#include "core/film/film.h"
#include "core/image_io/image_input.h"
#include "core/scene/scene.h"
#include "core/scene_file/scene_loader.h"
#include "kernels/adaptive/decision_schedule.h"
#include "kernels/adaptive/stopping_rule.h"
#include "kernels/reference_integrator.h"
#include "kernels/renderer.h"

namespace {

using namespace wt;

struct Samples {
    int width = 0, height = 0;
    uint32_t spp = 0;
    std::vector<glm::vec3> values;  // pixel-major: values[pixel * spp + sample]
    const glm::vec3* of(std::size_t pixel) const { return &values[pixel * spp]; }
};

Samples trace_all(const Scene& scene, uint32_t spp, int threads) {
    Samples s{scene.settings.width, scene.settings.height, spp, {}};
    const std::size_t pixels = std::size_t(s.width) * std::size_t(s.height);
    s.values.resize(pixels * spp);
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&] {
            RayCounts counts;
            for (std::size_t p; (p = next++) < pixels;)
                for (uint32_t i = 0; i < spp; ++i) {
                    glm::vec3 v = trace_reference_path(scene, uint32_t(p), i, counts);
                    if (!std::isfinite(v.x + v.y + v.z)) v = glm::vec3(0.0f);  // the film drops these; none expected
                    s.values[p * spp + i] = v;
                }
        });
    for (std::thread& w : workers) w.join();
    return s;
}

// Per pixel, what the rule has seen so far.
struct Running {
    glm::dvec3 sum{0.0}, square{0.0}, even{0.0};
    uint32_t n = 0, stop = 0;  // stop 0: still sampled
};

double normaliser(const glm::dvec3& mean) {
    const double i = std::max(0.0, mean.x + mean.y + mean.z);
    return 1e-4 + (i < 1.0 ? std::sqrt(i) : i);
}

double error_of(const Running& r, bool half) {
    const double n = r.n;
    const glm::dvec3 mean = r.sum / n;
    if (half) {  // Cycles: A holds twice the even samples; error Σ|I - A| / n, threshold scaled by 5
        const glm::dvec3 d = glm::abs(r.sum - 2.0 * r.even) / n;
        return (d.x + d.y + d.z) / normaliser(mean) / 5.0;
    }
    const glm::dvec3 variance = glm::max(glm::dvec3(0.0), (r.square / n - mean * mean) * (n / (n - 1)));
    return (std::sqrt(variance.x / n) + std::sqrt(variance.y / n) + std::sqrt(variance.z / n)) / normaliser(mean);
}

struct Row {
    double mean_spp = 0, rmse = 0, rel_mse = 0, mean_ratio = 0;  // mean ratio: sum of the image / sum of the reference
};

Row image_error_of(const Samples& s, const std::vector<Running>& pixels, const ImageData& reference) {
    Row row;
    double squared = 0, relative = 0, spent = 0, image_sum = 0, reference_sum = 0;
    const std::vector<float> r = reference.channel("R"), g = reference.channel("G"), b = reference.channel("B");
    for (std::size_t p = 0; p < pixels.size(); ++p) {
        const glm::dvec3 mean = pixels[p].sum / double(pixels[p].n);
        const double ref[3] = {r[p], g[p], b[p]};
        for (int c = 0; c < 3; ++c) {
            const double e = mean[c] - ref[c];
            squared += e * e;
            relative += e * e / (ref[c] * ref[c] + 0.01);
            image_sum += mean[c], reference_sum += ref[c];
        }
        spent += pixels[p].n;
    }
    const double values = 3.0 * double(pixels.size());
    row.mean_spp = spent / double(pixels.size());
    row.rmse = std::sqrt(squared / values);
    row.rel_mse = relative / values;
    row.mean_ratio = image_sum / reference_sum;
    (void)s;
    return row;
}

void add(Running& r, const glm::vec3& v, uint32_t index) {
    const glm::dvec3 d(v);
    r.sum += d, r.square += d * d, r.n += 1;
    if (index % 2 == 0) r.even += d;
}

// Uniform sampling at `spp`.
Row uniform(const Samples& s, uint32_t spp, const ImageData& reference) {
    std::vector<Running> pixels(std::size_t(s.width) * std::size_t(s.height));
    for (std::size_t p = 0; p < pixels.size(); ++p)
        for (uint32_t i = 0; i < spp; ++i) add(pixels[p], s.of(p)[i], i);
    return image_error_of(s, pixels, reference);
}

// The renderer's rule (decision points, unconverged set dilated by one pixel, final stops) on
// the traced samples, with one of the two errors.
Row adaptive(const Samples& s, const AdaptiveSettings& settings, bool half, const ImageData& reference) {
    const int w = s.width, h = s.height;
    std::vector<Running> pixels(std::size_t(w) * std::size_t(h));
    std::vector<uint8_t> unconverged(pixels.size());
    for (uint32_t done = 0; done < s.spp;) {
        if (is_decision_point(settings, done)) {
            for (std::size_t p = 0; p < pixels.size(); ++p)
                unconverged[p] = pixels[p].stop == 0 && !(error_of(pixels[p], half) < settings.threshold);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    Running& r = pixels[std::size_t(y) * std::size_t(w) + std::size_t(x)];
                    if (r.stop) continue;
                    bool keep = false;
                    for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1); ++ny)
                        for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx)
                            keep |= unconverged[std::size_t(ny) * std::size_t(w) + std::size_t(nx)] != 0;
                    if (!keep) r.stop = done;
                }
        }
        const uint32_t end = std::min(s.spp, next_decision_point(settings, done));
        for (std::size_t p = 0; p < pixels.size(); ++p)
            if (!pixels[p].stop)
                for (uint32_t i = done; i < end; ++i) add(pixels[p], s.of(p)[i], i);
        done = end;
    }
    return image_error_of(s, pixels, reference);
}

int table(int argc, char** argv) {
    SceneDescription d = load_scene_file(argv[1]);
    const ImageData reference = read_image(argv[2]);
    d.settings.width = std::atoi(argv[3]), d.settings.height = std::atoi(argv[4]);
    const uint32_t max_spp = uint32_t(std::atoi(argv[5]));
    std::vector<int> min_spps;
    for (const char* p = argv[6]; *p;) {
        char* end = nullptr;
        min_spps.push_back(int(std::strtol(p, &end, 10)));
        p = *end == ',' ? end + 1 : end;
    }
    const int threads = argc > 7 ? std::atoi(argv[7]) : 2;
    if (reference.width != d.settings.width || reference.height != d.settings.height) {
        std::fprintf(stderr, "the reference is %dx%d\n", reference.width, reference.height);
        return 1;
    }
    const Scene scene = build_scene(d);
    const Samples samples = trace_all(scene, max_spp, threads);
    std::printf("estimate,min_spp,threshold,mean_spp,rmse,rel_mse,mean_ratio\n");
    for (uint32_t spp = 4; spp <= max_spp; spp *= 2) {
        const Row r = uniform(samples, spp, reference);
        std::printf("uniform,-,0,%.2f,%.6f,%.6f,%.5f\n", r.mean_spp, r.rmse, r.rel_mse, r.mean_ratio);
    }
    // The half image's error is about sqrt(2/pi) / 5 of the standard error's for the same noise
    // (pixel_error.h): its ladder is the same one divided by 6, so both span the same spp.
    AdaptiveSettings settings;
    for (const int min_spp : min_spps)
        for (const bool half : {false, true})
            for (const float t : {0.8f, 0.4f, 0.3f, 0.2f, 0.15f, 0.1f, 0.07f, 0.05f, 0.035f}) {
                settings.min_spp = min_spp;
                settings.threshold = half ? t / 6.0f : t;
                const Row r = adaptive(samples, settings, half, reference);
                std::printf("%s,%d,%g,%.2f,%.6f,%.6f,%.5f\n", half ? "half" : "se", min_spp, double(settings.threshold),
                            r.mean_spp, r.rmse, r.rel_mse, r.mean_ratio);
            }
    return 0;
}

int film_cost(int extra_channels) {
    std::vector<std::string> names;
    for (int c = 0; c < extra_channels; ++c) names.push_back("half." + std::to_string(c));
    Film film(64, 64, names);
    const float extra[3] = {0.25f, 0.5f, 0.75f};
    CALLGRIND_TOGGLE_COLLECT;
    for (uint32_t i = 0; i < 1000000; ++i) {
        const float v = float(i % 977) * 0.01f;
        film.add_sample(i % 4096, glm::vec3(v, 0.5f * v, 0.25f * v), extra_channels ? extra : nullptr);
    }
    CALLGRIND_TOGGLE_COLLECT;
    std::printf("checksum %g\n", film.pixel_mean(5).x);
    return 0;
}

int rule_cost(const char* scene_path) {
    SceneDescription d = load_scene_file(scene_path);
    d.settings.width = d.settings.height = 200;
    d.settings.spp = 16;
    d.settings.adaptive.threshold = 0.1f;
    const Scene scene = build_scene(d);
    RenderOptions options;
    options.threads = 1;
    Film film(200, 200);
    render(scene, options, film);  // decides nothing: 16 samples end at the first decision point
    film.adaptive().stopped_at.assign(film.pixel_total(), AdaptiveState::still_sampling);
    CALLGRIND_TOGGLE_COLLECT;
    const uint32_t stopped = apply_stopping_rule(film, d.settings.adaptive, 16);
    CALLGRIND_TOGGLE_COLLECT;
    std::printf("checksum %u\n", stopped);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::string(argv[1]) == "film-cost") return film_cost(std::atoi(argv[2]));
    if (argc == 3 && std::string(argv[1]) == "rule-cost") return rule_cost(argv[2]);
    if (argc >= 7) return table(argc, argv);
    std::fprintf(stderr,
                 "usage: adaptive_estimators SCENE REFERENCE.exr WIDTH HEIGHT MAX_SPP MIN_SPP,... [THREADS]\n"
                 "       adaptive_estimators film-cost EXTRA_CHANNELS\n"
                 "       adaptive_estimators rule-cost SCENE\n");
    return 2;
}
