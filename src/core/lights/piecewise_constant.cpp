#include "core/lights/piecewise_constant.h"

#include <algorithm>
#include <cmath>

namespace wt {

namespace {

// cdf[0] = 0 ... cdf[n] = 1, in double and rounded once; all-zero weights count as equal.
std::vector<float> cumulative(const std::vector<double>& weights, double& total) {
    total = 0.0;
    for (double w : weights) total += w;
    const bool uniform = !(total > 0.0);
    std::vector<float> cdf(weights.size() + 1, 0.0f);
    double running = 0.0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        running += uniform ? 1.0 : weights[i];
        cdf[i + 1] = float(running / (uniform ? double(weights.size()) : total));
    }
    cdf.back() = 1.0f;
    return cdf;
}

// The last interval [cdf[i], cdf[i + 1]) holding u that is not empty.
std::size_t interval(const std::vector<float>& cdf, float u) {
    const auto it = std::upper_bound(cdf.begin() + 1, cdf.end(), u);
    return std::min<std::size_t>(std::size_t(it - cdf.begin()) - 1, cdf.size() - 2);
}

}  // namespace

PiecewiseConstant1D::PiecewiseConstant1D(const std::vector<double>& weights) {
    double total = 0.0;
    cdf_ = cumulative(weights, total);
    const double n = double(weights.size());
    mean_ = total / n;
    density_.resize(weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i) density_[i] = float(mean_ > 0.0 ? weights[i] / mean_ : 1.0);
}

float PiecewiseConstant1D::sample(float u, uint32_t& cell) const {
    const std::size_t i = interval(cdf_, u);
    cell = uint32_t(i);
    const float width = cdf_[i + 1] - cdf_[i];
    const float within = width > 0.0f ? std::clamp((u - cdf_[i]) / width, 0.0f, 1.0f) : 0.5f;
    const float x = (float(i) + within) / float(size());
    // Never 1, and never past the cell (rounding of the division): the cell decides the density.
    return std::min(x, std::nextafter((float(i) + 1.0f) / float(size()), 0.0f));
}

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<double>& weights, int width, int height)
    : width_(width), height_(height) {
    std::vector<double> row_totals(std::size_t(height), 0.0);
    columns_.reserve(std::size_t(height));
    for (int y = 0; y < height; ++y) {
        const auto first = weights.begin() + std::ptrdiff_t(y) * width;
        std::vector<double> row(first, first + width);
        for (double w : row) row_totals[std::size_t(y)] += w;
        columns_.emplace_back(row);
    }
    rows_ = PiecewiseConstant1D(row_totals);
}

glm::vec2 PiecewiseConstant2D::sample(float u0, float u1, float& density) const {
    uint32_t row = 0, column = 0;
    const float y = rows_.sample(u1, row);
    const float x = columns_[row].sample(u0, column);
    density = rows_.density(row) * columns_[row].density(column);
    return {x, y};
}

float PiecewiseConstant2D::density(glm::vec2 p) const {
    const int column = std::clamp(int(p.x * float(width_)), 0, width_ - 1);
    const int row = std::clamp(int(p.y * float(height_)), 0, height_ - 1);
    return rows_.density(uint32_t(row)) * columns_[std::size_t(row)].density(uint32_t(column));
}

DiscreteDistribution::DiscreteDistribution(const std::vector<double>& weights) {
    double total = 0.0;
    cdf_ = cumulative(weights, total);
    probability_.resize(weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i) probability_[i] = cdf_[i + 1] - cdf_[i];
}

std::size_t DiscreteDistribution::pick(float u, float& rescaled) const {
    const std::size_t i = interval(cdf_, u);
    const float width = cdf_[i + 1] - cdf_[i];
    rescaled = width > 0.0f ? std::clamp((u - cdf_[i]) / width, 0.0f, std::nextafter(1.0f, 0.0f)) : 0.0f;
    return i;
}

std::size_t PiecewiseConstant2D::bytes() const {
    std::size_t bytes = rows_.bytes() + columns_.capacity() * sizeof(PiecewiseConstant1D);
    for (const PiecewiseConstant1D& column : columns_) bytes += column.bytes();
    return bytes;
}

}  // namespace wt
