#include "core/film/aov.h"

#include <algorithm>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace wt {

namespace {

// Film channel names of the per-path values. Depth is summed over the samples that hit
// something ("Z") with their count beside it, so a pixel half on a wall and half on nothing
// gets the wall's depth, not half of it.
const char* const albedo_channels[] = {"albedo.R", "albedo.G", "albedo.B"};
const char* const normal_channels[] = {"N.R", "N.G", "N.B"};
const char* const depth_channel = "Z";
const char* const coverage_channel = "Z.coverage";

std::size_t channel_index(const Film& film, const std::string& name) {
    const auto& channels = film.extra_channels();
    const auto it = std::find(channels.begin(), channels.end(), name);
    if (it == channels.end()) throw std::invalid_argument("AOVs: the film has no channel '" + name + "'");
    return std::size_t(it - channels.begin());
}

}  // namespace

AovSelection parse_aov_list(const std::string& text) {
    const std::string choices = "' (choose from albedo, normal, depth, variance, samples, or all; comma-separated)";
    AovSelection s;
    // getline drops a trailing empty field, so "albedo," is caught by the check on the last character.
    if (text.empty() || text.back() == ',') throw std::invalid_argument("empty AOV name in '" + text + choices);
    std::istringstream in(text);
    std::string word;
    while (std::getline(in, word, ',')) {
        if (word == "albedo") s.albedo = true;
        else if (word == "normal") s.normal = true;
        else if (word == "depth") s.depth = true;
        else if (word == "variance") s.variance = true;
        else if (word == "samples") s.samples = true;
        else if (word == "all") s.albedo = s.normal = s.depth = s.variance = s.samples = true;
        else if (word.empty()) throw std::invalid_argument("empty AOV name in '" + text + choices);
        else throw std::invalid_argument("unknown AOV '" + word + "' in '" + text + choices);
    }
    return s;
}

AovSelection aovs_held_by(const Film& film) {
    const auto has = [&](const char* name) {
        const auto& c = film.extra_channels();
        return std::find(c.begin(), c.end(), name) != c.end();
    };
    AovSelection s;
    s.albedo = has(albedo_channels[0]);
    s.normal = has(normal_channels[0]);
    s.depth = has(depth_channel) && has(coverage_channel);
    return s;
}

std::vector<std::string> aov_film_channels(const AovSelection& aovs) {
    std::vector<std::string> channels;
    if (aovs.albedo) channels.insert(channels.end(), std::begin(albedo_channels), std::end(albedo_channels));
    if (aovs.normal) channels.insert(channels.end(), std::begin(normal_channels), std::end(normal_channels));
    if (aovs.depth) channels.insert(channels.end(), {depth_channel, coverage_channel});
    return channels;
}

std::vector<std::string> film_channels_for(const AovSelection& aovs, bool with_splats) {
    std::vector<std::string> channels = aov_film_channels(aovs);
    if (with_splats) channels.insert(channels.end(), std::begin(Film::splat_channels), std::end(Film::splat_channels));
    return channels;
}

void aov_sample_values(const AovSelection& aovs, const FirstSurface& surface, float* out) {
    if (aovs.albedo) *out++ = surface.albedo.x, *out++ = surface.albedo.y, *out++ = surface.albedo.z;
    if (aovs.normal) *out++ = surface.normal.x, *out++ = surface.normal.y, *out++ = surface.normal.z;
    if (aovs.depth) *out++ = surface.depth, *out++ = surface.coverage;
}

ImageChannels resolve_aovs(const Film& film, const AovSelection& aovs) {
    ImageChannels image;
    std::vector<std::size_t> averaged;  // film channels written as their mean
    for (const std::string& name : aov_film_channels(aovs)) {
        if (name == coverage_channel) continue;
        image.names.push_back(name);
        averaged.push_back(channel_index(film, name));
    }
    if (aovs.variance) image.names.insert(image.names.end(), {"variance.R", "variance.G", "variance.B"});
    if (aovs.samples) image.names.push_back("samples.Y");
    if (image.names.empty()) return image;

    const std::size_t depth = aovs.depth ? channel_index(film, depth_channel) : 0;
    const std::size_t coverage = aovs.depth ? channel_index(film, coverage_channel) : 0;
    const std::size_t n = image.names.size();
    image.values.resize(film.pixel_total() * n);
    for (uint32_t p = 0; p < film.pixel_total(); ++p) {
        float* out = &image.values[p * n];
        for (std::size_t c : averaged) {
            if (aovs.depth && c == depth) {
                // No sample hit anything: infinitely far, OpenEXR's reading of a Z with nothing there.
                const double hits = film.extra_mean(p, coverage);
                *out++ = hits > 0.0 ? float(film.extra_mean(p, depth) / hits) : std::numeric_limits<float>::infinity();
            } else {
                *out++ = float(film.extra_mean(p, c));
            }
        }
        if (aovs.variance) {
            // Of the pixel's mean: one sample's variance over the count (0 with fewer than two samples).
            const uint32_t count = film.pixel_count(p);
            const glm::dvec3 v = count ? film.pixel_sample_variance(p) / double(count) : glm::dvec3(0.0);
            *out++ = float(v.x), *out++ = float(v.y), *out++ = float(v.z);
        }
        if (aovs.samples) *out++ = float(film.pixel_count(p));
    }
    return image;
}

}  // namespace wt
