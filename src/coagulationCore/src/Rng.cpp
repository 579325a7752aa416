#include "coagulation/Rng.hpp"

#include <sstream>
#include <stdexcept>

namespace coag {

namespace {
__extension__ typedef unsigned __int128 uint128;
}

std::uint64_t Rng::uniformIndex(std::uint64_t n)
{
    if (n == 0) {
        throw std::invalid_argument("coag::Rng::uniformIndex: n must be > 0");
    }
    // Lemire, "Fast random integer generation in an interval" (2019).
    uint128 m = static_cast<uint128>(engine_()) * n;
    std::uint64_t low = static_cast<std::uint64_t>(m);
    if (low < n) {
        const std::uint64_t threshold = (0 - n) % n;
        while (low < threshold) {
            m = static_cast<uint128>(engine_()) * n;
            low = static_cast<std::uint64_t>(m);
        }
    }
    return static_cast<std::uint64_t>(m >> 64);
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
