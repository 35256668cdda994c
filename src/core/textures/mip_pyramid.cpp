#include "core/textures/mip_pyramid.h"

#include <algorithm>
#include <cmath>

#include "core/textures/srgb.h"

namespace wt {

namespace {

// Source index range and weights of destination texel i when n texels shrink to m: the
// destination texel covers [i n / m, (i + 1) n / m) of the source.
struct Footprint {
    int first, last;           // inclusive
    float first_weight, last_weight;  // coverage of the end texels; inner ones are covered fully
    float inverse_width;       // m / n: normalises the weights to sum 1
};

Footprint footprint(int i, int n, int m) {
    const double lo = double(i) * n / m, hi = double(i + 1) * n / m;
    Footprint f;
    f.first = int(std::floor(lo));
    f.last = std::min(n - 1, int(std::ceil(hi)) - 1);
    f.first_weight = float(std::min(hi, double(f.first + 1)) - lo);
    f.last_weight = f.last == f.first ? f.first_weight : float(hi - double(f.last));
    f.inverse_width = float(double(m) / double(n));
    return f;
}

float weight_of(const Footprint& f, int j) {
    if (j == f.first) return f.first_weight;
    if (j == f.last) return f.last_weight;
    return 1.0f;
}

}  // namespace

MipLevel box_downsample(const MipLevel& source) {
    MipLevel out;
    out.width = std::max(1, source.width / 2);
    out.height = std::max(1, source.height / 2);
    out.texels.resize(std::size_t(out.width) * std::size_t(out.height));
    for (int y = 0; y < out.height; ++y) {
        const Footprint fy = footprint(y, source.height, out.height);
        for (int x = 0; x < out.width; ++x) {
            const Footprint fx = footprint(x, source.width, out.width);
            glm::vec4 sum(0.0f);
            for (int sy = fy.first; sy <= fy.last; ++sy)
                for (int sx = fx.first; sx <= fx.last; ++sx)
                    sum += (weight_of(fy, sy) * weight_of(fx, sx)) * source.at(sx, sy);
            out.texels[std::size_t(y) * std::size_t(out.width) + std::size_t(x)] = sum * (fx.inverse_width * fy.inverse_width);
        }
    }
    return out;
}

MipPyramid::MipPyramid(const TextureImage& image)
    : name_(image.name), wrap_s_(image.wrap_s), wrap_t_(image.wrap_t), coordinate_set_(image.coordinate_set) {
    MipLevel base;
    base.width = image.texels->width;
    base.height = image.texels->height;
    base.texels = image.texels->rgba;
    // Into [0, 1], NaN to 0, before anything else: a float file's texels (EXR) may be anything,
    // and every lookup is then a convex combination of reflectances, never NaN nor above one.
    const auto unit = [](float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; };
    for (glm::vec4& t : base.texels) {
        t = glm::vec4(unit(t.x), unit(t.y), unit(t.z), unit(t.w));
        if (image.srgb) t = glm::vec4(srgb_to_linear(t.x), srgb_to_linear(t.y), srgb_to_linear(t.z), t.w);
    }
    log2_texel_scale_ = 0.5f * std::log2(float(base.width) * float(base.height));
    if (image.offset != glm::vec2(0.0f) || image.scale != glm::vec2(1.0f) || image.rotation != 0.0f) {
        // T R S with R = [cos sin; -sin cos] (KHR_texture_transform's matrices).
        const float c = std::cos(image.rotation), s = std::sin(image.rotation);
        transformed_ = true;
        row0_ = glm::vec3(c * image.scale.x, s * image.scale.y, image.offset.x);
        row1_ = glm::vec3(-s * image.scale.x, c * image.scale.y, image.offset.y);
        // A scaled map packs more texels into each unit of the coordinates it is given.
        const float det = std::fabs(image.scale.x * image.scale.y);
        if (det > 0.0f && std::isfinite(det)) log2_texel_scale_ += 0.5f * std::log2(det);
    }
    std::vector<MipLevel> levels;
    levels.push_back(std::move(base));
    while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(box_downsample(levels.back()));
    levels_ = std::make_shared<const std::vector<MipLevel>>(std::move(levels));
}

std::size_t MipPyramid::bytes() const {
    std::size_t b = 0;
    if (levels_)
        for (const MipLevel& l : *levels_) b += l.texels.size() * sizeof(glm::vec4);
    return b;
}

}  // namespace wt
