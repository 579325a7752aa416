#ifndef COAGULATION_RNG_HPP
#define COAGULATION_RNG_HPP

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

namespace coag {

//- One seeded generator per cell population (std::mt19937_64 inside).
class Rng {
public:
    explicit Rng(std::uint64_t seed) : engine_(seed) {}

    //- Uniform on the open interval (0,1): 53 random bits, centred in their bin.
    double uniform()
    {
        return (static_cast<double>(engine_() >> 11) + 0.5) * (1.0 / 9007199254740992.0);  // 2^-53
    }

    //- Exponentially distributed with the given rate (> 0).
    double exponential(double rate) { return -std::log(uniform()) / rate; }

    //- Uniform on {0, ..., n-1}, unbiased (Lemire's method); n must be > 0.
    std::uint64_t uniformIndex(std::uint64_t n);

    //- Full generator state as text (std::mt19937_64 stream format).
    std::string state() const;

    //- Restore a state written by state(); throws std::invalid_argument on bad text.
    void setState(const std::string& s);

    std::mt19937_64& engine() { return engine_; }

private:
    std::mt19937_64 engine_;
};

} // namespace coag

#endif
