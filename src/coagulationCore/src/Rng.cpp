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
    os << engine_;
    return os.str();
}

void Rng::setState(const std::string& s)
{
    std::istringstream is(s);
    std::mt19937_64 e;
    is >> e;
    if (is.fail()) {
        throw std::invalid_argument("coag::Rng::setState: text is not a std::mt19937_64 state");
    }
    engine_ = e;
}

} // namespace coag
