#pragma once
// The AOVs (arbitrary output variables) a render can write beside the beauty image, for
// denoisers (OIDN's albedo and normal guides) and compositing (depth), and to judge the noise
// (variance of the mean, sample count). Which ones a render keeps decides the film's extra
// channels; with none, no AOV data is carried or computed anywhere.

#include <string>
#include <vector>

#include "core/film/film.h"
#include "core/film/image_channels.h"
#include "core/path/first_surface.h"

namespace wt {

struct AovSelection {
    bool albedo = false, normal = false, depth = false, variance = false, samples = false;

    bool any() const { return albedo || normal || depth || variance || samples; }
    // albedo, normal and depth come from each path; variance and samples from the film alone.
    bool needs_path_data() const { return albedo || normal || depth; }
    bool operator==(const AovSelection& o) const {
        return albedo == o.albedo && normal == o.normal && depth == o.depth && variance == o.variance && samples == o.samples;
    }
};

// "albedo,normal,depth,variance,samples" in any order and combination, or "all". Throws
// std::invalid_argument naming the word that is not an AOV and listing the ones that are.
AovSelection parse_aov_list(const std::string& text);

// The per-sample AOVs (albedo, normal, depth) whose channels `film` has: what a film read from a
// checkpoint or merged from partial renders can show.
AovSelection aovs_held_by(const Film& film);

// The film's extra channels for `aovs`, in the order aov_sample_values writes them.
std::vector<std::string> aov_film_channels(const AovSelection& aovs);

// The whole film's extra channels: the AOVs', then Film::splat_channels if the render splats.
std::vector<std::string> film_channels_for(const AovSelection& aovs, bool with_splats);

// One sample's extra-channel values (aov_film_channels(aovs).size() floats) into `out`.
void aov_sample_values(const AovSelection& aovs, const FirstSurface& surface, float* out);

// The AOV layers of an image, channels named as written to EXR (`albedo.R`, `N.R`, `Z`, ...),
// from a film made with aov_film_channels(aovs). Empty when nothing is selected. Throws
// std::invalid_argument if the film lacks a channel the selection needs.
ImageChannels resolve_aovs(const Film& film, const AovSelection& aovs);

}  // namespace wt
