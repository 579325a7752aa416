/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "sizeDistribution.H"
#include "particleMaterial.H"
#include "coagulationCloud.H"
#include "addToRunTimeSelectionTable.H"
#include "fvMesh.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "caseChecks.H"

#include <cmath>
#include <sstream>

namespace Foam
{
namespace coagulation
{
namespace cloudFunctions
{
    defineTypeNameAndDebug(sizeDistribution, 0);
    addToRunTimeSelectionTable(cloudFunction, sizeDistribution, dictionary);
}
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

coag::SizeBins Foam::coagulation::cloudFunctions::sizeDistribution::readBins
(
    const dictionary& dict
)
{
    const word type(dict.get<word>("type"));
    if (type == "integer")
    {
        caseChecks::keywords(dict, {"type", "K"});
        const label K = dict.get<label>("K");
        if (K < 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'K' = " << K << " in " << dict.name()
                << " must be at least 1 (the bins k = 1..K)" << nl
                << exit(FatalIOError);
        }
        return coag::SizeBins::integer(std::size_t(K));
    }
    if (type == "log")
    {
        caseChecks::keywords(dict, {"type", "min", "max", "nBins"});
        const scalar mMin = caseChecks::positive(dict, "min");
        const scalar mMax = caseChecks::positive(dict, "max");
        const label nBins = dict.get<label>("nBins");
        if (!(mMax > mMin) || nBins < 1)
        {
            FatalIOErrorInFunction(dict)
                << "Entries 'min' = " << mMin << ", 'max' = " << mMax
                << ", 'nBins' = " << nBins << " in " << dict.name()
                << ": log bins need min < max and nBins >= 1" << nl
                << exit(FatalIOError);
        }
        return coag::SizeBins::logarithmic(mMin, mMax, std::size_t(nBins));
    }
    FatalIOErrorInFunction(dict)
        << "Entry 'type' = " << type << " in " << dict.name()
        << " is not a kind of bins; valid: (integer log)" << nl
        << exit(FatalIOError);
    return coag::SizeBins::integer(1);
}


void Foam::coagulation::cloudFunctions::sizeDistribution::readRegions
(
    const dictionary& dict
)
{
    const fvMesh& mesh = cloud_.mesh();
    const List<vector> probes
    (
        dict.getOrDefault<List<vector>>("probes", List<vector>())
    );
    const wordList zones
    (
        dict.getOrDefault<wordList>("cellZones", wordList())
    );
    if (probes.empty() && zones.empty())
    {
        FatalIOErrorInFunction(dict)
            << "Neither 'probes' nor 'cellZones' in " << dict.name()
            << ": the size distribution needs at least one region" << nl
            << exit(FatalIOError);
    }

    const label n = probes.size() + zones.size();
    regionNames_.setSize(n);
    regionPoints_.setSize(n);
    regionCells_.setSize(n);
    regionVolumes_.setSize(n);
    regionMin_.setSize(n);
    regionMax_.setSize(n);

    const pointField& pts = mesh.points();
    auto box = [&](const label r)
    {
        vector lo(vector::uniform(GREAT)), hi(vector::uniform(-GREAT));
        for (const label celli : regionCells_[r])
        {
            for (const label pointi : mesh.cellPoints()[celli])
            {
                lo = min(lo, pts[pointi]);
                hi = max(hi, pts[pointi]);
            }
        }
        reduce(lo, minOp<vector>());
        reduce(hi, maxOp<vector>());
        regionMin_[r] = lo;
        regionMax_[r] = hi;
    };

    forAll(probes, i)
    {
        const label celli = mesh.findCell(probes[i]);
        // a point on a processor boundary belongs to the lowest processor
        const label owner = returnReduce
        (
            celli >= 0 ? Pstream::myProcNo() : Pstream::nProcs(),
            minOp<label>()
        );
        if (owner == Pstream::nProcs())
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'probes' of " << dict.name() << ": the point "
                << probes[i] << " is in no cell of the mesh" << nl
                << exit(FatalIOError);
        }
        regionNames_[i] = "probe" + Foam::name(i);
        regionPoints_[i] = probes[i];
        regionCells_[i] =
            (owner == Pstream::myProcNo()) ? labelList(1, celli) : labelList();
        regionVolumes_[i] = returnReduce
        (
            regionCells_[i].size() ? mesh.V()[celli] : 0.0,
            sumOp<scalar>()
        );
        box(i);
    }

    forAll(zones, j)
    {
        const label r = probes.size() + j;
        const label zonei = mesh.cellZones().findZoneID(zones[j]);
        if (zonei < 0)
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'cellZones' of " << dict.name() << ": cellZone '"
                << zones[j] << "' is not in the mesh; its cellZones are "
                << mesh.cellZones().names() << nl << exit(FatalIOError);
        }
        regionNames_[r] = zones[j];
        regionCells_[r] = mesh.cellZones()[zonei];
        scalar V = 0;
        vector VC(Zero);
        for (const label celli : regionCells_[r])
        {
            V += mesh.V()[celli];
            VC += mesh.V()[celli]*mesh.C()[celli];
        }
        reduce(V, sumOp<scalar>());
        reduce(VC, sumOp<vector>());
        if (!(V > 0))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'cellZones' of " << dict.name() << ": cellZone '"
                << zones[j] << "' has no cell" << nl << exit(FatalIOError);
        }
        regionVolumes_[r] = V;
        regionPoints_[r] = VC/V;
        box(r);
    }
}


Foam::label
Foam::coagulation::cloudFunctions::sizeDistribution::nColumns() const
{
    return label(bins_.size()) + 2 + label(coag::DerivedSizes::names().size());
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::cloudFunctions::sizeDistribution::sizeDistribution
(
    const word& name,
    const dictionary& dict,
    coagulationCloud& cloud
)
:
    cloudFunction(cloud),
    name_(name),
    bins_(coag::SizeBins::integer(1)),
    timeStart_(0),
    stepsPerSample_(1),
    sampleInterval_(0),
    minWindow_(0),
    density_(0),
    massUnit_(1),
    series_(),
    writer_(),
    file_(),
    values_(),
    seconds_(0),
    nSamples_(0)
{
    const Time& runTime = cloud.pMesh().time();

    caseChecks::movedEntries
    (
        dict,
        {
            {"density", "the particles' material, 'particles { density ...; }',"},
            {"massUnit", "the particles' material, 'particles { massUnit ...; }',"}
        }
    );
    caseChecks::keywords
    (
        dict,
        {
            "type", "probes", "cellZones", "bins", "timeStart",
            "sampleInterval", "correlationTime"
        }
    );

    bins_ = readBins(dict.subDict("bins"));
    timeStart_ = caseChecks::nonNegative(dict, "timeStart");
    sampleInterval_ =
        dict.found("sampleInterval")
      ? caseChecks::positive(dict, "sampleInterval")
      : cloud.properties().subDict("sampling").get<scalar>("sampleInterval");
    // Samples of whole split steps (stepInterval time steps each)
    stepsPerSample_ =
        cloud.stepInterval()
       *caseChecks::stepsPer
        (
            dict, "sampleInterval", sampleInterval_, cloud.splitDeltaT()
        );
    if (timeStart_ >= runTime.endTime().value())
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'timeStart' = " << timeStart_ << " in " << dict.name()
            << " is not before endTime " << runTime.endTime().value()
            << ": no sample would be taken" << nl << exit(FatalIOError);
    }
    const scalar Tc = dict.getOrDefault<scalar>("correlationTime", 0);
    if (!(Tc >= 0) || !(Tc/sampleInterval_ < 1e9))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'correlationTime' = " << Tc << " in " << dict.name()
            << " must be a non-negative time of at most 1e9 sample intervals"
            << nl << exit(FatalIOError);
    }
    minWindow_ = label(std::ceil(Tc/sampleInterval_ - 1e-9));
    // Diameters from the particles' material, when the case gives one
    if (cloud.properties().found("particles"))
    {
        const coag::ParticleMaterial material =
            readParticleMaterial(cloud.properties(), "size distribution " + name);
        density_ = material.density;
        massUnit_ = material.massUnit;
    }

    readRegions(dict);

    if (Pstream::master())
    {
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/name_/runTime.timeName()
        );
        mkDir(dir);
        file_ = dir/"sizeDistribution.h5";

        std::vector<std::array<double, 3>> points(regionPoints_.size());
        forAll(regionPoints_, r)
        {
            points[r] =
            {
                regionPoints_[r].x(), regionPoints_[r].y(),
                regionPoints_[r].z()
            };
        }
        series_.assign
        (
            regionPoints_.size(),
            std::vector<std::vector<double>>(nColumns())
        );
        values_.resize(regionPoints_.size()*nColumns());

        std::ostringstream columns, edges, regions, volumes;
        columns.precision(17);
        edges.precision(17);
        volumes.precision(17);
        for (std::size_t i = 0; i < bins_.size(); ++i)
        {
            columns << (i ? " " : "") << "n" << i;
        }
        columns << " underflow overflow";
        for (const std::string& s : coag::DerivedSizes::names())
        {
            columns << " " << s;
        }
        for (std::size_t i = 0; i < bins_.edges().size(); ++i)
        {
            edges << (i ? " " : "") << bins_.edges()[i];
        }
        forAll(regionNames_, r)
        {
            regions << (r ? " " : "") << regionNames_[r];
            volumes << (r ? " " : "") << regionVolumes_[r];
        }

        try
        {
            writer_.reset
            (
                new coag::MomentSeriesWriter(file_, points, int(nColumns()))
            );
            writer_->setAttribute("columns", columns.str());
            writer_->setAttribute("binEdges", edges.str());
            writer_->setAttribute
            (
                "binType", bins_.isInteger() ? "integer" : "log"
            );
            writer_->setAttribute("regions", regions.str());
            writer_->setAttribute("regionVolumes", volumes.str());
            writer_->setAttribute("timeStart", timeStart_);
            writer_->setAttribute("correlationTime", Tc);
            writer_->setAttribute("sampleInterval", sampleInterval_);
            writer_->setAttribute("density", density_);
            writer_->setAttribute("massUnit", massUnit_);
            writer_->setAttribute("K0", cloud.kernel().K0());
            writer_->setAttribute
            (
                "inceptionRate", cloud.inception().core().rate
            );
            writer_->setAttribute
            (
                "kernel",
                cloud.properties().subDict("kernel").get<word>("type")
            );
        }
        catch (const std::exception& e)
        {
            FatalErrorInFunction
                << "Cannot create the size distribution file " << file_
                << ": " << e.what() << nl << exit(FatalError);
        }
    }

    Info<< "Size distribution " << name_ << ": " << regionNames_.size()
        << " region(s), " << bins_.size() << " bins, every "
        << stepsPerSample_ << " steps from t = " << timeStart_ << nl << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::cloudFunctions::sizeDistribution::sample()
{
    const Time& runTime = cloud_.pMesh().time();
    if
    (
        runTime.timeIndex() % stepsPerSample_ != 0
     || runTime.value() < timeStart_ - 1e-9*runTime.deltaTValue()
    )
    {
        return;
    }
    const auto start = std::chrono::steady_clock::now();

    // The particles are sorted by cell (momentFields' postStep, before)
    const cellParticleIndex& index = cloud_.index();
    const labelList& cellStart = index.cellStart();
    const DynamicList<coagulationParticle*>& particles = index.cellParticles();
    const label nc = nColumns();

    forAll(regionCells_, r)
    {
        List<scalarList> masses(Pstream::nProcs());
        List<scalarList> weights(Pstream::nProcs());
        {
            DynamicList<scalar> m, w;
            for (const label celli : regionCells_[r])
            {
                for (label i = cellStart[celli]; i < cellStart[celli + 1]; ++i)
                {
                    m.append(particles[i]->mass());
                    w.append(particles[i]->weight());
                }
            }
            masses[Pstream::myProcNo()].transfer(m);
            weights[Pstream::myProcNo()].transfer(w);
        }
        Pstream::gatherList(masses);
        Pstream::gatherList(weights);

        if (!Pstream::master())
        {
            continue;
        }
        std::vector<double> m, w;
        forAll(masses, proci)
        {
            m.insert(m.end(), masses[proci].begin(), masses[proci].end());
            w.insert(w.end(), weights[proci].begin(), weights[proci].end());
        }
        const coag::SizeSample s = coag::sizeSample
        (
            m, w, regionVolumes_[r], bins_, density_, massUnit_
        );
        std::vector<double> row(s.numberDensity);
        row.push_back(s.underflow);
        row.push_back(s.overflow);
        const std::vector<double> d = s.derived.values();
        row.insert(row.end(), d.begin(), d.end());
        for (label j = 0; j < nc; ++j)
        {
            values_[r*nc + j] = row[j];
            series_[r][j].push_back(row[j]);
        }
    }

    if (Pstream::master())
    {
        writer_->append(runTime.value(), values_);
    }
    ++nSamples_;
    seconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
}


void Foam::coagulation::cloudFunctions::sizeDistribution::writeAverages() const
{
    const Time& runTime = cloud_.pMesh().time();
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/name_/runTime.timeName()
    );
    mkDir(dir);

    // Derived sizes are undefined (NaN) in samples without a particle: their
    // averages are over the samples that have one
    auto stats = [this](const label r, const label j)
    {
        const std::vector<double>& all = series_[r][j];
        std::vector<double> x;
        x.reserve(all.size());
        for (const double v : all)
        {
            if (std::isfinite(v))
            {
                x.push_back(v);
            }
        }
        return coag::correlatedMean(x, std::size_t(minWindow_));
    };
    auto put = [](OFstream& os, const coag::CorrelatedMean& c)
    {
        os  << ',' << c.mean << ',' << c.sd << ',' << label(c.count)
            << ',' << c.tauInt << ',' << c.neff << ',' << c.ci95 << nl;
    };

    OFstream regions(dir/"regions.csv");
    regions.precision(12);
    regions
        << "region,name,x,y,z,volume,xMin,yMin,zMin,xMax,yMax,zMax" << nl;
    forAll(regionNames_, r)
    {
        const vector& p = regionPoints_[r];
        const vector& lo = regionMin_[r];
        const vector& hi = regionMax_[r];
        regions
            << r << ',' << regionNames_[r] << ',' << p.x() << ',' << p.y()
            << ',' << p.z() << ',' << regionVolumes_[r] << ',' << lo.x()
            << ',' << lo.y() << ',' << lo.z() << ',' << hi.x() << ','
            << hi.y() << ',' << hi.z() << nl;
    }

    OFstream psd(dir/"sizeDistribution.csv");
    psd.precision(10);
    psd << "# number density per bin (1/m^3), time average from t = "
        << timeStart_ << "; ci95: 95 % interval of the mean for correlated"
        << " samples (integrated autocorrelation time tauInt, effective"
        << " sample size neff); bin -1 underflow, " << label(bins_.size())
        << " overflow" << nl
        << "region,bin,lower,upper,centre,mean,sd,count,tauInt,neff,ci95"
        << nl;
    const label nb = label(bins_.size());
    forAll(regionNames_, r)
    {
        for (label i = -1; i <= nb; ++i)
        {
            const label j = (i < 0) ? nb : (i == nb ? nb + 1 : i);
            const scalar lower = (i < 0) ? 0 : bins_.edges()[std::min(i, nb)];
            const scalar upper =
                (i < 0) ? bins_.edges().front()
              : (i == nb ? GREAT : bins_.edges()[i + 1]);
            const scalar centre =
                (i < 0 || i == nb) ? 0 : bins_.centre(std::size_t(i));
            psd << r << ',' << i << ',' << lower << ',' << upper << ','
                << centre;
            put(psd, stats(r, j));
        }
    }

    OFstream derived(dir/"derived.csv");
    derived.precision(10);
    derived
        << "# sizes from the particles of each sample, time-averaged from t = "
        << timeStart_ << "; masses in the particles' unit, diameters (m) of"
        << " spheres of density " << density_ << " kg/m^3 (NaN without)" << nl
        << "region,quantity,mean,sd,count,tauInt,neff,ci95" << nl;
    const std::vector<std::string> names = coag::DerivedSizes::names();
    forAll(regionNames_, r)
    {
        for (std::size_t q = 0; q < names.size(); ++q)
        {
            derived << r << ',' << names[q].c_str();
            put(derived, stats(r, nb + 2 + label(q)));
        }
    }
}


void Foam::coagulation::cloudFunctions::sizeDistribution::flush()
{
    if (!writer_)
    {
        return;
    }
    try
    {
        writer_->flush();
    }
    catch (const std::exception& e)
    {
        FatalErrorInFunction
            << "Cannot write the size distribution samples to " << file_
            << " (disk full?): " << e.what() << nl << exit(FatalError);
    }
}


void Foam::coagulation::cloudFunctions::sizeDistribution::write()
{
    const auto start = std::chrono::steady_clock::now();
    // Before timeStart there is nothing to average
    if (Pstream::master() && nSamples_ > 0)
    {
        writeAverages();
        flush();
    }
    seconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
}


void Foam::coagulation::cloudFunctions::sizeDistribution::end()
{
    const auto start = std::chrono::steady_clock::now();
    flush();
    seconds_ += std::chrono::duration<double>
    (
        std::chrono::steady_clock::now() - start
    ).count();
    Info<< "Size distribution " << name_ << ": " << nSamples_
        << " samples, wall time in the function " << seconds_ << " s"
        << " (this processor)" << nl << endl;
}


// ************************************************************************* //
