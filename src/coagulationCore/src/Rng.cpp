// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/Rng.hpp"

#include <sstream>
#include <stdexcept>

namespace coag {

void Rng::throwZeroRange()
{
    throw std::invalid_argument("coag::Rng::uniformIndex: n must be > 0");
}

std::string Rng::state() const
{
    std::ostringstream os;
    os << "xoshiro256++";
    for (const std::uint64_t w : engine_.words()) os << ' ' << w;
    return os.str();
}

void Rng::setState(const std::string& s)
{
    std::istringstream is(s);
    std::string name;
    std::array<std::uint64_t, 4> w{};
    is >> name >> w[0] >> w[1] >> w[2] >> w[3];
    std::string rest;
    if (is.fail() || name != "xoshiro256++" || (is >> rest) || !engine_.setWords(w)) {
        throw std::invalid_argument("coag::Rng::setState: text is not an xoshiro256++ state "
                                    "(the name and four words, not all zero)");
    }
}

} // namespace coag
