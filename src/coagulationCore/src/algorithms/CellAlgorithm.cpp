// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
// The algorithms by name: SWA (SwaAlgorithm.cpp), DSA1 and DSA2 (DsaAlgorithm.cpp), sharing
// the jump process of JumpProcess.hpp.
#include "coagulation/algorithms/CellAlgorithm.hpp"
#include "coagulation/algorithms/EventLoop.hpp"
#include "JumpProcess.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace coag {

std::vector<std::string> cellAlgorithmNames()
{
    return {"SWA", "DSA1", "DSA2"};
}

std::unique_ptr<CellAlgorithm> makeCellAlgorithm(const std::string& name,
                                                 const CoagulationKernel& kernel,
                                                 const InceptionModel& inception,
                                                 const NumberControl& control)
{
    return detail::makeCellAlgorithm(name, kernel, inception, control, DrawsAhead::whereTheyPay);
}

std::unique_ptr<CellAlgorithm> detail::makeCellAlgorithm(const std::string& name,
                                                         const CoagulationKernel& kernel,
                                                         const InceptionModel& inception,
                                                         const NumberControl& control,
                                                         DrawsAhead drawsAhead)
{
    if (!(inception.rate >= 0.0) || !std::isfinite(inception.rate)) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: inception rate must be finite and >= 0, got "
           << inception.rate;
        throw std::invalid_argument(os.str());
    }
    if (!(inception.weight > 0.0) || !std::isfinite(inception.weight)) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: inception weight must be finite and > 0, got "
           << inception.weight;
        throw std::invalid_argument(os.str());
    }
    if (!(inception.type.mass > 0.0) || !std::isfinite(inception.type.mass)) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: incepted particle mass must be finite and > 0, got "
           << inception.type.mass;
        throw std::invalid_argument(os.str());
    }
    if (control.maxParticles > 0 && control.minParticles > 0
        && control.maxParticles < 2 * control.minParticles) {
        std::ostringstream os;
        os << "coag::makeCellAlgorithm: number control needs maxParticles >= 2*minParticles, got "
           << control.maxParticles << " and " << control.minParticles;
        throw std::invalid_argument(os.str());
    }
    if (name == "SWA") return detail::makeSwa(kernel, inception, control, drawsAhead);
    if (name == "DSA1") return detail::makeDsa1(kernel, inception, control, drawsAhead);
    if (name == "DSA2") return detail::makeDsa2(kernel, inception, control, drawsAhead);
    std::ostringstream os;
    os << "coag::makeCellAlgorithm: unknown algorithm '" << name << "'; valid names are:";
    for (const std::string& n : cellAlgorithmNames()) os << ' ' << n;
    throw std::invalid_argument(os.str());
}

} // namespace coag
