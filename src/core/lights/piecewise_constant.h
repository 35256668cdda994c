#pragma once
// Piecewise-constant distributions for sampling in proportion to a table of weights: over [0, 1)
// in one dimension, and over the unit square as a marginal over rows times a conditional over
// each row's columns (pbrt, "Piecewise-Constant 2D Distributions", sec. 13.6.7 of the 3rd
// edition), which is how an environment map is sampled by its texels (environment_light.h).

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace wt {

class PiecewiseConstant1D {
public:
    PiecewiseConstant1D() = default;
    // Weights must be non-negative and finite; all zero samples uniformly.
    explicit PiecewiseConstant1D(const std::vector<double>& weights);

    std::size_t size() const { return density_.size(); }
    double mean() const { return mean_; }  // of the weights, before any zero fallback

    // A point x in [0, 1) with density density(cell) in cell floor(x * size()). u in [0, 1).
    float sample(float u, uint32_t& cell) const;
    // Density per unit x of every point in the cell: weight / mean.
    float density(uint32_t cell) const { return density_[cell]; }
    std::size_t bytes() const { return (cdf_.capacity() + density_.capacity()) * sizeof(float); }

private:
    std::vector<float> cdf_;      // size() + 1, from 0 to exactly 1
    std::vector<float> density_;  // size()
    double mean_ = 0.0;
};

// Over [0, 1)^2, weights row-major (`width` per row, row 0 at v = 0).
class PiecewiseConstant2D {
public:
    PiecewiseConstant2D() = default;
    PiecewiseConstant2D(const std::vector<double>& weights, int width, int height);

    // (x, y) in [0, 1)^2 with density density(x, y) per unit area.
    glm::vec2 sample(float u0, float u1, float& density) const;
    float density(glm::vec2 p) const;
    std::size_t bytes() const;

private:
    int width_ = 0, height_ = 0;
    PiecewiseConstant1D rows_;               // the marginal: each row's total weight
    std::vector<PiecewiseConstant1D> columns_;  // the conditional in each row
};

// A discrete choice among n items in proportion to weights (light selection by power).
class DiscreteDistribution {
public:
    DiscreteDistribution() = default;
    explicit DiscreteDistribution(const std::vector<double>& weights);  // all zero: uniform

    std::size_t size() const { return probability_.size(); }
    float probability(std::size_t i) const { return probability_[i]; }
    // The item u in [0, 1) picks; `rescaled` is u's position within the item's interval, itself
    // uniform in [0, 1), for the item's own sampling.
    std::size_t pick(float u, float& rescaled) const;
    std::size_t bytes() const { return (cdf_.capacity() + probability_.capacity()) * sizeof(float); }

private:
    std::vector<float> cdf_;  // size() + 1
    std::vector<float> probability_;
};

}  // namespace wt
