// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_COAGULATION_HPP
#define COAGULATION_COAGULATION_HPP

//- Umbrella header of the coagulationCore library (namespace coag), one folder per concept.
//  The public headers compile as C++14 as well, and none includes HDF5 or Eigen. The
//  references the tests check against are a library of their own (coagulationReferences/).
#include "coagulation/random/Rng.hpp"
#include "coagulation/random/SplitMix64.hpp"
#include "coagulation/random/CounterStream.hpp"
#include "coagulation/random/Normal.hpp"
#include "coagulation/population/ParticleType.hpp"
#include "coagulation/population/Particle.hpp"
#include "coagulation/population/CellPopulation.hpp"
#include "coagulation/population/Inception.hpp"
#include "coagulation/population/LargeArray.hpp"
#include "coagulation/kernels/CoagulationKernel.hpp"
#include "coagulation/kernels/BrownianKernel.hpp"
#include "coagulation/kernels/GravitationalSettlingKernel.hpp"
#include "coagulation/kernels/SumKernel.hpp"
#include "coagulation/aerosol/AerosolProperties.hpp"
#include "coagulation/sampling/QuantizedSumTree.hpp"
#include "coagulation/sampling/MajorantSampler.hpp"
#include "coagulation/algorithms/CellAlgorithm.hpp"
#include "coagulation/algorithms/NumberControl.hpp"
#include "coagulation/algorithms/StepStatistics.hpp"
#include "coagulation/growth/GrowthLaw.hpp"
#include "coagulation/growth/Growth.hpp"
#include "coagulation/transport/Dispersion.hpp"
#include "coagulation/output/MomentSeriesFile.hpp"
#include "coagulation/output/SizeDistribution.hpp"
#include "coagulation/statistics/Moments.hpp"
#include "coagulation/statistics/RunningStatistics.hpp"
#include "coagulation/statistics/CompensatedSum.hpp"
#include "coagulation/statistics/CorrelatedMean.hpp"
#include "coagulation/decomposition/WorkPartition.hpp"
#include "coagulation/decomposition/CostFit.hpp"

#endif
