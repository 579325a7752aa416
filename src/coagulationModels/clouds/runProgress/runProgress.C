/*---------------------------------------------------------------------------*\
  coagulationFoam: weighted stochastic particles coupled to OpenFOAM
  Copyright (C) 2025-2026 the coagulationFoam authors
  SPDX-License-Identifier: GPL-3.0-or-later (see COPYING); links OpenFOAM,
  which is GPL-3.0-or-later too
\*---------------------------------------------------------------------------*/

#include "runProgress.H"
#include "Switch.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

enum class stepLines { on, off, automatic };

//- Runs of at most this many steps get a line every step (auto)
constexpr Foam::label maxLoggedSteps = 500;

//- A wall time for the log: seconds, or h:mm:ss from a minute on
Foam::string wallTime(const Foam::scalar seconds)
{
    if (seconds < 60)
    {
        return Foam::name(std::round(10*seconds)/10) + " s";
    }
    const long s = std::lround(seconds);
    char buffer[32];
    std::snprintf
    (
        buffer, sizeof(buffer), "%ld:%02ld:%02ld", s/3600, (s/60)%60, s%60
    );
    return buffer;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::coagulation::runProgress::runProgress(const Time& runTime)
:
    runTime_(runTime),
    startIndex_(runTime.timeIndex()),
    steps_(0),
    everyStep_(false),
    interval_(10),
    start_(clock::now()),
    lastLine_(start_)
{
    // The steps to endTime; unknown (-1) where the run stops otherwise
    // (stopAt nextWrite, writeNow, ...) or endTime is out of reach
    const dictionary& controls = runTime.controlDict();
    const scalar span = runTime.endTime().value() - runTime.value();
    const scalar dt = runTime.deltaTValue();
    steps_ =
        runTime.stopAt() == Time::saEndTime && span < 0.25*labelMax*dt
      ? max(label(std::round(span/dt)), label(0))
      : -1;

    // auto, or any of OpenFOAM's switch words (on/off, yes/no, true/false,
    // y/n, t/f, none)
    const word logSteps(controls.getOrDefault<word>("logSteps", "auto"));
    const Switch asSwitch(logSteps, true);
    if (logSteps != "auto" && !asSwitch.valid())
    {
        FatalIOErrorInFunction(controls)
            << "Entry 'logSteps' in " << controls.name() << " is '" << logSteps
            << "'; valid values are auto or a switch (on, off, yes, no,"
            << " true, false)" << nl << exit(FatalIOError);
    }
    const stepLines lines =
        logSteps == "auto"
      ? stepLines::automatic
      : (asSwitch ? stepLines::on : stepLines::off);
    everyStep_ =
        lines == stepLines::on
     || (
            lines == stepLines::automatic
         && 0 <= steps_ && steps_ <= maxLoggedSteps
        );

    if (controls.found("progressInterval"))
    {
        interval_ = controls.get<scalar>("progressInterval");
        if (!(interval_ > 0) || !std::isfinite(interval_))
        {
            FatalIOErrorInFunction(controls)
                << "Entry 'progressInterval' in " << controls.name()
                << " must be a number of seconds > 0, got " << interval_
                << nl << exit(FatalIOError);
        }
    }
    if (!everyStep_)
    {
        Info<< "Progress: a line at every write and every " << interval_
            << " s of wall time (";
        if (steps_ >= 0)
        {
            Info<< steps_ << " steps; ";
        }
        Info<< "'logSteps on;' in " << controls.name().name()
            << " for a line every step)" << nl << endl;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::coagulation::runProgress::elapsed() const
{
    return std::chrono::duration<double>(clock::now() - start_).count();
}


void Foam::coagulation::runProgress::line(const label particles)
{
    lastLine_ = clock::now();
    const label done = runTime_.timeIndex() - startIndex_;
    const scalar seconds = elapsed();
    const scalar rate = seconds > 0 ? done/seconds : 0;
    Info<< "Time = " << runTime_.timeName() << "  (";
    if (steps_ > 0)
    {
        Info<< label(std::floor(100.0*done/steps_)) << " %, step " << done
            << " of " << steps_;
    }
    else
    {
        Info<< "step " << done;
    }
    Info<< ", " << Foam::name(std::round(10*rate)/10).c_str() << " steps/s, "
        << wallTime(seconds).c_str() << " so far";
    if (rate > 0 && steps_ > done)
    {
        Info<< ", about " << wallTime((steps_ - done)/rate).c_str() << " left";
    }
    Info<< "), " << particles << " particles" << endl;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::coagulation::runProgress::step(const label localParticles) const
{
    if (everyStep_)
    {
        Info<< "Time = " << runTime_.timeName() << "  particles = "
            << returnReduce(localParticles, sumOp<label>()) << nl;
    }
}


void Foam::coagulation::runProgress::afterStep
(
    const label localParticles,
    const bool written
)
{
    if (everyStep_)
    {
        return;
    }
    // Every processor decides alike: the master's clock
    bool due =
        written
     || std::chrono::duration<double>(clock::now() - lastLine_).count()
     >= interval_;
    Pstream::scatter(due);
    if (due)
    {
        line(returnReduce(localParticles, sumOp<label>()));
    }
}


void Foam::coagulation::runProgress::end() const
{
    const label done = runTime_.timeIndex() - startIndex_;
    const scalar seconds = elapsed();
    Info<< "Run: " << done << " steps in " << wallTime(seconds).c_str()
        << " of wall time";
    if (seconds > 0)
    {
        Info<< ", " << Foam::name(std::round(10*done/seconds)/10).c_str()
            << " steps/s";
    }
    Info<< nl << endl;
}


// ************************************************************************* //
