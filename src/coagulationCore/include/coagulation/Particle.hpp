#ifndef COAGULATION_PARTICLE_HPP
#define COAGULATION_PARTICLE_HPP

#include "coagulation/ParticleType.hpp"

#include <array>
#include <cstdint>

namespace coag {

//- One computational particle.
struct Particle {
    ParticleType type;
    double weight = 1.0;                 //!< statistical weight: number of physical particles represented
    std::array<double, 3> position{};    //!< carried along, untouched by the cell algorithms
    std::int64_t tag = -1;               //!< caller's handle; -1 for particles the algorithm created
};

} // namespace coag

#endif
