// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COAGULATION_HPP
#define COAGULATION_COAGULATION_HPP

//- Umbrella header of the coagulationCore library (namespace coag). The public headers
//  compile as C++14 as well, and none includes HDF5. The Eigen-based deterministic references
//  (SmoluchowskiReference.hpp) are left out so that users need no Eigen include path;
//  include that header directly where needed.
#include "coagulation/CellAlgorithm.hpp"
#include "coagulation/CellPopulation.hpp"
#include "coagulation/CoagulationKernel.hpp"
#include "coagulation/Dispersion.hpp"
#include "coagulation/ExactSolutions.hpp"
#include "coagulation/Inception.hpp"
#include "coagulation/LargeArray.hpp"
#include "coagulation/MomentSeriesFile.hpp"
#include "coagulation/Moments.hpp"
#include "coagulation/NanbuMethod.hpp"
#include "coagulation/NumberControl.hpp"
#include "coagulation/Particle.hpp"
#include "coagulation/ParticleType.hpp"
#include "coagulation/PseudoTurbulence.hpp"
#include "coagulation/Rng.hpp"
#include "coagulation/QuantizedSumTree.hpp"
#include "coagulation/SizeDistribution.hpp"
#include "coagulation/WorkPartition.hpp"
#include "coagulation/CostFit.hpp"

#endif
