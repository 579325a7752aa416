// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_PARTICLETYPE_HPP
#define COAGULATION_PARTICLETYPE_HPP

namespace coag {

//- The particle "type" z of the papers. Today only the mass; a multi-component type
//  can add fields later (operator+ must then merge them, and mass must stay the
//  total mass, which the SWA weight update and DSA2 use).
struct ParticleType {
    double mass = 1.0;
};

//- Coagulation merges types: masses add.
inline ParticleType operator+(const ParticleType& a, const ParticleType& b)
{
    return ParticleType{a.mass + b.mass};
}

} // namespace coag

#endif
