#!/bin/bash
# Every entry of constant/coagulationProperties, missing, wrong or unknown (a typo), and
# the time controls that would make a run do nothing, stop the solver with an OpenFOAM
# FatalIOError that names the file and the entry (no crash, no silent default).
. "$(dirname "$0")/caseLib.sh"

base=$(newCase constantKernelDuct badInput_base)
passed=0

# expectFatal name expectedText foamDictionaryArgs...   (on $file, coagulationProperties
# unless set)
file=constant/coagulationProperties
expectFatal()
{
    local name="$1" expected="$2"; shift 2
    local case="$workDir/badInput_$name"
    rm -rf "$case"; cp -r "$base" "$case"
    (cd "$case" && foamDictionary "$file" "$@" > /dev/null)
    checkFatal "$name" "$expected" "$case" "$file"
}

# checkFatal name expectedText case editedFile: the run stops with a FatalIOError naming
# the text and the file
checkFatal()
{
    local name="$1" expected="$2" case="$3" edited="$4"
    if coagulationFoam -case "$case" > "$case/log" 2>&1; then
        fail "$name: coagulationFoam accepted bad input"
    fi
    grep -q "FOAM FATAL IO ERROR" "$case/log" || { tail -20 "$case/log"; fail "$name: no FatalIOError"; }
    grep -q -- "$expected" "$case/log" || { tail -20 "$case/log"; fail "$name: error does not name '$expected'"; }
    grep -q "$(basename "$edited")" "$case/log" || fail "$name: error does not name the file"
    passed=$((passed + 1))
    echo "ok $name"
}

expectFatal missingAlgorithm   "algorithm"        -entry algorithm -remove
expectFatal unknownAlgorithm   "DSA3"             -entry algorithm -set DSA3
expectFatal unknownSplitting   "Strange"          -entry splitting -set Strange
expectFatal stickNoWall        "matches no wall"  -entry patchInteraction -add "{ patches { sides stick; } }"
expectFatal interactionTypo   "patchs"           -entry patchInteraction -add "{ patchs { sides stick; } }"
expectFatal unknownInteraction "StandardWall"    -entry patchInteraction -add "{ type StandardWall; patches { } }"
expectFatal missingKernel      "kernel"           -entry kernel -remove
expectFatal unknownKernel      "quadratic"        -entry kernel/type -set quadratic
expectFatal missingK0          "K0"               -entry kernel/K0 -remove
expectFatal negativeK0         "K0"               -entry kernel/K0 -set -1
expectFatal zeroK0             "type none"        -entry kernel/K0 -set 0
expectFatal noneWithK0         "Unknown entry 'K0'" -entry kernel -set "{ type none; K0 1e-5; }"
expectFatal negativeRate       "rate"             -entry inception/rate -set -3e8
expectFatal missingRate        "rate"             -entry inception/rate -remove
expectFatal zeroMass           "mass"             -entry inception/mass -set 0
expectFatal unknownZone        "flame"            -entry inception/cellZone -set flame
expectFatal missingPatch       "nozzle"           -entry inflow/patches -set "(nozzle)"
expectFatal negativeDensity    "density"          -entry inflow/density -set -1
expectFatal missingN           "'n'"              -entry statisticalWeight/n -remove
expectFatal zeroV1             "SWA"              -entry statisticalWeight/V1/SWA -set 0
expectFatal missingSeed        "seed"             -entry seed -remove
expectFatal negativeSeed       "seed"             -entry seed -set -5
expectFatal missingSampling    "sampling"         -entry sampling -remove
expectFatal badSampleInterval  "sampleInterval"   -entry sampling/sampleInterval -set 1.5e-4

# Unknown keywords are typos, in every dictionary
expectFatal unknownTopLevel    "inceptoin"        -entry inceptoin -set "{ rate 1; }"
expectFatal typoCellZone       "cellzone"         -entry inception/cellzone -set flame
expectFatal typoInflow         "inflw"            -entry inflw -set "{ patches (inlet); density 1e9; mass 1; }"
expectFatal typoMaxParticles   "maxParticlesPerCel" -entry numberControl -set "{ maxParticlesPerCel 100; }"
expectFatal typoKernel         "K00"              -entry kernel/K00 -set 1
expectFatal typoSampling       "tRelx"            -entry sampling/tRelx -set 1
expectFatal typoV1             "SWB"              -entry statisticalWeight/V1/SWB -set 1
# Every run-time selectable part: an unknown type or keyword lists the valid ones
expectFatal unknownTransport   "frozenFlow"       -entry transport -set "{ type brownian; }"
expectFatal typoTransport      "tpye"             -entry transport -set "{ tpye frozenFlow; }"
expectFatal unknownInception   "cellZone"         -entry inception/type -set pointSource
expectFatal uniformWithZone    "type uniform"     -entry inception -set "{ type uniform; rate 1; mass 1; cellZone flame; }"
expectFatal unknownInjection   "patchInflow"      -entry inflow/type -set nozzle
# Values that used to be taken without a word
expectFatal negativeMaxParticles "maxParticlesPerCell" -entry numberControl -set "{ maxParticlesPerCell -1; }"
expectFatal oneMaxParticles    "maxParticlesPerCell" -entry numberControl -set "{ maxParticlesPerCell 1; }"
expectFatal inflowOnOutlet     "no inward flow"   -entry inflow -set "{ patches (outlet); density 1e9; mass 1; }"
expectFatal inflowNoPatches    "lists no patch"   -entry inflow -set "{ patches (); density 1e9; mass 1; }"
expectFatal longSampleInterval "sampleInterval"   -entry sampling/sampleInterval -set 5
# The random walk and the initial population
expectFatal unknownInterpolation "cubic"          -entry transport -set "{ type frozenFlow; interpolationSchemes { U cubic; } }"
expectFatal typoInterpolation  "'u'"              -entry transport -set "{ type frozenFlow; interpolationSchemes { u cellPoint; } }"
expectFatal maxCoAboveOne      "maxCo"            -entry transport -set "{ type frozenFlow; interpolationSchemes { U cellPoint; } maxCo 2; }"
expectFatal unknownDispersion  "random"           -entry dispersion -set "{ type random; }"
expectFatal typoDispersion     "Dt"               -entry dispersion -set "{ type constant; Dt 1e-3; }"
expectFatal negativeD          "'D'"              -entry dispersion -set "{ type constant; D -1e-3; }"
expectFatal zeroSct            "Sct"              -entry dispersion -set "{ type turbulent; Sct 0; }"
expectFatal missingNut         "reads the field 'nut'" -entry dispersion -set "{ type turbulent; Sct 0.7; }"
expectFatal brownianNoT        "'T'"              -entry dispersion -set "{ type Brownian; mu 1.8e-5; lambda 6.6e-8; }"
expectFatal brownianRho        "'rho'.*no longer read here.*particles" -entry dispersion -set "{ type Brownian; T 300; mu 1.8e-5; lambda 6.6e-8; rho 1000; }"
expectFatal brownianDispersionNoParticles "Brownian dispersion needs the particles' material" -entry dispersion -set "{ type Brownian; T 300; mu 1.8e-5; lambda 6.6e-8; }"
expectFatal initialZone        "nowhere"          -entry initialPopulation -set "{ numberDensity 1e9; mass 1; cellZone nowhere; }"
expectFatal initialBoth        "exactly one"      -entry initialPopulation -set "{ numberDensity 1e9; numberDensityField n0; mass 1; }"
expectFatal initialNoField     "'n0'"             -entry initialPopulation -set "{ numberDensityField n0; mass 1; }"
expectFatal initialBadTable    "sizeDistribution" -entry initialPopulation -set "{ numberDensity 1e9; sizeDistribution ((1 -0.5)); }"
expectFatal initialTypo        "numberDensty"     -entry initialPopulation -set "{ numberDensty 1e9; mass 1; }"
expectFatal initialTooMany     "free memory"      -entry initialPopulation -set "{ numberDensity 1e30; mass 1; }"
# The user's cloud functions (sizeDistribution)
psdOk="type sizeDistribution; probes ((0.098 0.002 0.002)); bins { type integer; K 30; } timeStart 0.4;"
expectFatal psdUnknownType     "sizeDist"         -entry cloudFunctions -set "{ psd1 { type sizeDist; } }"
expectFatal psdNotDict         "not a dictionary" -entry cloudFunctions -set "{ psd1 sizeDistribution; }"
expectFatal psdTypo            "probs"            -entry cloudFunctions -set "{ psd1 { $psdOk probs ((0.1 0.002 0.002)); } }"
expectFatal psdProbeOutside    "in no cell"       -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((5 0.002 0.002)); bins { type integer; K 30; } timeStart 0.4; } }"
expectFatal psdNoRegion        "Neither 'probes'" -entry cloudFunctions -set "{ psd1 { type sizeDistribution; bins { type integer; K 30; } timeStart 0.4; } }"
expectFatal psdUnknownZone     "flame"            -entry cloudFunctions -set "{ psd1 { $psdOk cellZones (flame); } }"
expectFatal psdBinType         "linear"           -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((0.098 0.002 0.002)); bins { type linear; K 30; } timeStart 0.4; } }"
expectFatal psdLogBins         "min < max"        -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((0.098 0.002 0.002)); bins { type log; min 10; max 1; nBins 5; } timeStart 0.4; } }"
expectFatal psdBinTypo         "nbins"            -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((0.098 0.002 0.002)); bins { type log; min 1; max 100; nbins 5; } timeStart 0.4; } }"
expectFatal psdZeroK           "'K'"              -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((0.098 0.002 0.002)); bins { type integer; K 0; } timeStart 0.4; } }"
expectFatal psdMissingBins     "bins"             -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((0.098 0.002 0.002)); timeStart 0.4; } }"
expectFatal psdSampleInterval  "sampleInterval"   -entry cloudFunctions -set "{ psd1 { $psdOk sampleInterval 1.5e-4; } }"
expectFatal psdLateStart       "timeStart"        -entry cloudFunctions -set "{ psd1 { type sizeDistribution; probes ((0.098 0.002 0.002)); bins { type integer; K 30; } timeStart 100; } }"
expectFatal psdDensity         "'density'.*no longer read here.*particles" -entry cloudFunctions -set "{ psd1 { $psdOk density 1800; } }"
expectFatal psdMassUnit        "'massUnit'.*no longer read here" -entry cloudFunctions -set "{ psd1 { $psdOk massUnit 1e-24; } }"
expectFatal psdTopTypo         "cloudFunction"    -entry cloudFunction -set "{ psd1 { $psdOk } }"
expectFatal hugeSampleInterval "sampleInterval"   -entry sampling/sampleInterval -set 1e30
expectFatal psdHugeCorrelation "correlationTime"  -entry cloudFunctions -set "{ psd1 { $psdOk correlationTime 1e300; } }"
expectFatal cellWorkTypo       "field"            -entry cloudFunctions -set "{ work { type cellWork; field w; } }"
expectFatal cellWorkEventCost  "eventCost"        -entry cloudFunctions -set "{ work { type cellWork; eventCost -1; } }"
file=system/controlDict
expectFatal endTimeBelowStep   "endTime"          -entry endTime -set 4e-5
expectFatal courantAboveOne    "deltaT"           -entry deltaT -set 0.01
file=constant/coagulationProperties

# Field-driven sources: fields in the start time of the base case, a
# rate field negative in cell 7 and a positive epsilon; no constant/transportProperties
"$COAGULATIONFOAM_PYTHON" - "$base" <<'PY'
import sys
for name, dims, values in (("inceptionRate", "[0 -3 -1 0 0 0 0]", ["1e8"] * 7 + ["-1"] + ["1e8"] * 42),
                           ("epsilon", "[0 2 -3 0 0 0 0]", ["1e-3"] * 50)):
    with open("%s/0/%s" % (sys.argv[1], name), "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class volScalarField; object %s; }\n" % name)
        f.write("dimensions %s;\ninternalField nonuniform List<scalar> 50 (%s);\n" % (dims, " ".join(values)))
        f.write('boundaryField { ".*" { type zeroGradient; } sides { type empty; } }\n')
PY
expectFatal missingRateField   "model 'field'.*'sootRate'.*0/sootRate" -entry inception -set "{ type field; field sootRate; mass 1; }"
expectFatal negativeRateField  "'inceptionRate' in .*0/inceptionRate.*negative value -1 in cell 7" -entry inception -set "{ type field; field inceptionRate; mass 1; }"
expectFatal typoFieldInception "fild"             -entry inception -set "{ type field; fild inceptionRate; mass 1; }"
expectFatal rateWithField      "Unknown entry 'rate'" -entry inception -set "{ type field; field inceptionRate; rate 3e8; mass 1; }"
expectFatal missingEpsilon     "localSaffmanTurner.*'epsilonMean'.*0/epsilonMean" -entry kernel -set "{ type localSaffmanTurner; coefficient 1e-7; epsilon epsilonMean; nu 1e-5; }"
expectFatal missingNuField     "localSaffmanTurner.*'nuField'.*0/nuField" -entry kernel -set "{ type localSaffmanTurner; coefficient 1e-7; nu nuField; }"
expectFatal missingTransport   "localSaffmanTurner.*constant/transportProperties" -entry kernel -set "{ type localSaffmanTurner; coefficient 1e-7; }"
expectFatal typoLocalKernel    "epsilom"          -entry kernel -set "{ type localSaffmanTurner; coefficient 1e-7; nu 1e-5; epsilom epsilon; }"
expectFatal negativeCoefficient "coefficient"     -entry kernel -set "{ type localSaffmanTurner; coefficient -1; nu 1e-5; }"
expectFatal negativeNu         "nu = -1.*entry 'nu'" -entry kernel -set "{ type localSaffmanTurner; coefficient 1e-7; nu -1e-5; }"

# stopAt nextWrite (also writeNow, noWriteNow) leaves OpenFOAM's endTime at GREAT: the checks
# that count the run's steps must not overflow (it ended in SIGFPE) nor refuse the run
ok="$workDir/badInput_stopAtNextWrite"
rm -rf "$ok"; cp -r "$base" "$ok"
sed -i 's/^stopAt .*/stopAt          nextWrite;/' "$ok/system/controlDict"
coagulationFoam -case "$ok" > "$ok/log" 2>&1 || { tail -20 "$ok/log"; fail "stopAt nextWrite: the run failed"; }
[ "$(cd "$ok" && foamListTimes -noZero | tr '\n' ' ')" = "0.5 " ] || fail "stopAt nextWrite: did not stop at the first write, 0.5"
echo "ok stopAt nextWrite runs to the first write"

# The Brownian kernel and the particles' material
brownian="type Brownian; T 1500; p 1e5;"
expectFatal brownianNoParticles "needs the particles' material" -entry kernel -set "{ $brownian }"
expectFatal diameterNoParticles "inception (its 'diameter') needs the particles' material" -entry inception -set "{ rate 1e10; diameter 1e-8; }"
expectFatal massAndDiameter    "exactly one of 'mass'" -entry inception -set "{ rate 1e10; mass 1; diameter 1e-8; }"
expectFatal growthNoParticles  "growth model 'coat' needs the particles' material" -entry growth -set "{ coat { type surface; rate 1e-5; } }"
(cd "$base" && foamDictionary constant/coagulationProperties -entry particles \
    -add "{ density 1800; massUnit 9.42e-22; }" > /dev/null)

# Growth models
vapour="type condensation; concentration 1e-5; molarMass 0.098; diffusivity 1e-5; T 400;"
expectFatal growthNotDict      "'growth'.*must be a dictionary" -entry growth -set 5
expectFatal growthUnknownModel "sintering"        -entry growth -set "{ g { type sintering; } }"
expectFatal growthNoType       "type"             -entry growth -set "{ g { rate 1; } }"
expectFatal growthTypo         "rte"              -entry growth -set "{ g { type constant; rte 1; } }"
expectFatal growthMissingRate  "rate"             -entry growth -set "{ g { type linear; } }"
expectFatal growthNoModel      "lists no growth model" -entry growth -set "{ minimumMass 0; }"
expectFatal growthUnknownEntry "minimumMas"       -entry growth -set "{ minimumMas 0; g { type constant; rate 1; } }"
expectFatal growthBothMinimum  "not both"         -entry growth -set "{ minimumMass 0; minimumDiameter 1e-9; g { type constant; rate 1; } }"
expectFatal growthNegativeMinimum "minimumMass"   -entry growth -set "{ minimumMass -1; g { type constant; rate 1; } }"
expectFatal growthMinimumAboveInception "not above the minimum mass" -entry growth -set "{ minimumMass 2; g { type constant; rate 1; } }"
# the same without inception at the start (a rate of 0; a field's may rise later)
c="$workDir/badInput_growthMinimumNoInception"
rm -rf "$c"; cp -r "$base" "$c"
(cd "$c" && foamDictionary constant/coagulationProperties -entry inception/rate -set 0 > /dev/null \
    && foamDictionary constant/coagulationProperties -entry growth \
        -set "{ minimumMass 2; g { type constant; rate 1; } }" > /dev/null)
checkFatal growthMinimumNoInception "not above the minimum mass" "$c" constant/coagulationProperties
expectFatal growthMissingVapourField "'cVapour'.*0/cVapour" -entry growth -set "{ v { $vapour concentration cVapour; } }"
expectFatal growthNegativeDiffusivity "'diffusivity'" -entry growth -set "{ v { type condensation; concentration 1e-5; molarMass 0.098; diffusivity -1e-5; T 400; } }"
expectFatal growthAccommodation "'accommodation'" -entry growth -set "{ v { $vapour accommodation 1.5; } }"
expectFatal growthRegime       "slip"             -entry growth -set "{ v { $vapour regime slip; } }"
expectFatal growthNoT          "needs entry 'T'"  -entry growth -set "{ v { type condensation; concentration 1e-5; molarMass 0.098; diffusivity 1e-5; } }"
expectFatal growthNegativeConcentration "'concentration'" -entry growth -set "{ v { type condensation; concentration -1; molarMass 0.098; diffusivity 1e-5; T 400; } }"
expectFatal brownianRegime     "slipFlow"         -entry kernel -set "{ $brownian regime slipFlow; }"
expectFatal brownianTypo       "regim"            -entry kernel -set "{ $brownian regim transition; }"
expectFatal brownianNoTField   "'Brownian'.*'Tgas'.*0/Tgas" -entry kernel -set "{ type Brownian; T Tgas; p 1e5; }"
expectFatal brownianDefaultT   "'Brownian'.*'T'.*0/T" -entry kernel -set "{ type Brownian; p 1e5; }"
expectFatal brownianNegativeP  "'p' = -1"         -entry kernel -set "{ type Brownian; T 1500; p -1; }"
expectFatal brownianMu         "sutherlnd"        -entry kernel -set "{ $brownian mu sutherlnd; }"
# The settling kernel and sums of kernels
settling="type gravitationalSettling; T 1500; p 1e5;"
expectFatal settlingTypo       "colisionEfficiency" -entry kernel -set "{ $settling colisionEfficiency 0.5; }"
expectFatal settlingNegativeE  "collisionEfficiency" -entry kernel -set "{ $settling collisionEfficiency -0.5; }"
expectFatal settlingZeroG      "'g' = 0"          -entry kernel -set "{ $settling g 0; }"
expectFatal settlingNoTField   "'gravitationalSettling'.*'Tgas'.*0/Tgas" -entry kernel -set "{ type gravitationalSettling; T Tgas; p 1e5; }"
expectFatal sumOfNothing       "has no kernel"    -entry kernel -set "{ type sum; kernels { } }"
expectFatal sumNoKernels       "'kernels'"        -entry kernel -set "{ type sum; }"
expectFatal sumUnknownPart     "stokes"           -entry kernel -set "{ type sum; kernels { a { $brownian } b { type stokes; } } }"
expectFatal sumPartTwice       "both of type Brownian" -entry kernel -set "{ type sum; kernels { a { $brownian } b { $brownian } } }"
expectFatal sumPartTypo        "g0"               -entry kernel -set "{ type sum; kernels { s { $settling g0 9.81; } } }"
expectFatal sumTooLarge        "does not fit algorithm SWA.*sampler columns" -entry kernel -set "{ type sum; kernels { a { $brownian } b { $settling } c { type additive; K0 1e-20; } } }"
expectFatal particlesDensity   "'density' = -1"   -entry particles/density -set -1
expectFatal particlesTypo      "densty"           -entry particles -set "{ densty 1800; }"
expectFatal inflowDiameter     "'diameter' = -1"  -entry inflow -set "{ patches (inlet); density 1e9; diameter -1; }"
expectFatal tinyDiameter       "outside the range" -entry inception -set "{ rate 1e10; diameter 1e-120; }"
expectFatal initialSizeTwice   "exactly one of 'mass'" -entry initialPopulation -set "{ numberDensity 1e9; diameter 1e-8; sizeDistribution ((1 1)); }"

(cd "$base" && foamDictionary constant/coagulationProperties -entry algorithm -set DSA1 > /dev/null)
expectFatal dsaNumberControl   "maxParticlesPerCell" -entry numberControl -set "{ maxParticlesPerCell 100; }"

# expectFatalEdit name expectedText fileToEdit sedOrAppend: a case edited by hand (what
# foamDictionary cannot write: a duplicate entry, a field's dimensions)
expectFatalEdit()
{
    local name="$1" expected="$2" edited="$3" edit="$4"
    local case="$workDir/badInput_$name"
    rm -rf "$case"; cp -r "$base" "$case"
    case "$edit" in
        s/*) sed -i "$edit" "$case/$edited" ;;
        *) echo "$edit" >> "$case/$edited" ;;
    esac
    checkFatal "$name" "$expected" "$case" "$edited"
}
# A duplicate entry is refused, not silently the last one (a scalar, a sub-dictionary)
expectFatalEdit duplicateSeed   "duplicate entry: seed"   constant/coagulationProperties "seed 7;"
expectFatalEdit duplicateKernel "duplicate entry: kernel" constant/coagulationProperties "kernel { type constant; K0 2e-5; }"
# U must be a velocity
expectFatalEdit dimensionsU     "dimensions"              0/U "s/^dimensions .*/dimensions [0 1 0 0 0 0 0];/"
# The split steps are of the fixed deltaT: a Courant-limited step is refused, not ignored
expectFatalEdit adjustTimeStep  "adjustTimeStep"          system/controlDict "adjustTimeStep yes; maxCo 0.5;"
# The log's progress entries
expectFatalEdit logStepsValue   "logSteps"                system/controlDict "logSteps sometimes;"
expectFatalEdit progressZero    "progressInterval"        system/controlDict "progressInterval 0;"

echo "PASS bad input: $passed cases give a FatalIOError naming the entry"
