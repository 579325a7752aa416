// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_SIZEDISTRIBUTION_HPP
#define COAGULATION_SIZEDISTRIBUTION_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace coag {

//- Mass bins of a size distribution: either nBins log-spaced bins between min and max
//  (edges min*(max/min)^(i/nBins)), or the integer sizes k = 1..K of monomer units
//  (bin k holds masses in [k - 1/2, k + 1/2)). Masses below the first edge go to the
//  underflow, at or above the last edge to the overflow: every particle is counted once.
class SizeBins {
public:
    //- nBins log-spaced bins in [min, max); std::invalid_argument unless 0 < min < max
    //  (finite) and nBins >= 1.
    static SizeBins logarithmic(double min, double max, std::size_t nBins);
    //- Integer sizes k = 1..K (K >= 1), edges k - 1/2.
    static SizeBins integer(std::size_t K);

    std::size_t size() const { return edges_.size() - 1; }
    const std::vector<double>& edges() const { return edges_; }
    double lower(std::size_t i) const { return edges_[i]; }
    double upper(std::size_t i) const { return edges_[i + 1]; }
    //- The bin's representative mass: k for integer bins, the geometric mean of the edges
    //  for log bins.
    double centre(std::size_t i) const;
    bool isInteger() const { return integer_; }

    //- Bin index of mass m: 0..size()-1, or size() = underflow index, size()+1 = overflow.
    std::size_t index(double m) const;
    std::size_t underflow() const { return size(); }
    std::size_t overflow() const { return size() + 1; }

private:
    std::vector<double> edges_;
    bool integer_ = false;
    double logMin_ = 0, logWidth_ = 1;
};

//- Quantities derived from one population sample (from the particles directly, not from
//  the bins), in this order in values(); NaN where undefined (no particle; no density).
struct DerivedSizes {
    double M0 = 0;            // number density sum w / volume
    double meanMass = 0;      // M1/M0
    double geometricMean = 0; // exp(sum w ln m / sum w)
    double gsd = 0;           // geometric standard deviation exp(sqrt(sum w (ln m - ln mg)^2 / sum w))
    double median = 0;        // median mass of the number distribution (weighted, midpoint
                              // of the two middle masses where the cumulative weight is exactly 1/2)
    double d10 = 0;           // spheres of density rho: d = (6 m massUnit / (pi rho))^(1/3)
    double d32 = 0;           // sum w d^3 / sum w d^2
    double d43 = 0;           // sum w d^4 / sum w d^3

    static std::vector<std::string> names();
    std::vector<double> values() const;
};

//- One sample of the size distribution of a set of weighted particles in a volume:
//  number densities per bin (sum of weights / volume), under- and overflow, and the
//  derived sizes. density <= 0: the diameters are NaN. massUnit: physical mass of a unit
//  of the particles' mass (kg).
struct SizeSample {
    std::vector<double> numberDensity;   // [bins]
    double underflow = 0, overflow = 0;
    DerivedSizes derived;
};

SizeSample sizeSample(const std::vector<double>& masses, const std::vector<double>& weights,
                      double volume, const SizeBins& bins, double density = 0,
                      double massUnit = 1);

} // namespace coag

#endif
