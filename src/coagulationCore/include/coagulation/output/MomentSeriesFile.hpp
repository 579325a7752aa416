// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#ifndef COAGULATION_MOMENTSERIESFILE_HPP
#define COAGULATION_MOMENTSERIESFILE_HPP

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace coag {

//- Per-cell moment time series of one run, in HDF5 (the HDF5 headers stay in the .cpp).
//  Layout:
//    /cellCentres  double [nCells][3]
//    /time         double [nSamples]                    (extendible, chunked)
//    /moments      double [nSamples][nCells][nMoments]  (extendible, chunked)
//    root attributes: doubles and strings set with setAttribute.
//  The constructor creates (truncates) the file. HDF5 errors become std::runtime_error.
//
//  Crash safety: the file on disk is always a complete, closed HDF5 file. Samples are kept
//  in memory until flush(); every change (flush, setAttribute) is made to the file read
//  into memory (HDF5's core driver), whose image is written to <path>.tmp and renamed over
//  the file (rename(2) is atomic). A kill at any moment leaves the file as of the last
//  flush, and a failure (a full disk) leaves it untouched and throws std::runtime_error,
//  the unflushed samples still held for another try. The cost is reading and writing the
//  whole file per flush, and holding it in memory meanwhile: flush at write times, not at
//  every sample.
class MomentSeriesWriter {
public:
    MomentSeriesWriter(const std::string& path,
                       const std::vector<std::array<double, 3>>& cellCentres,
                       int nMoments = 4);
    ~MomentSeriesWriter();
    MomentSeriesWriter(MomentSeriesWriter&&) noexcept;
    MomentSeriesWriter& operator=(MomentSeriesWriter&&) noexcept;
    MomentSeriesWriter(const MomentSeriesWriter&) = delete;
    MomentSeriesWriter& operator=(const MomentSeriesWriter&) = delete;

    //- Create or overwrite a root attribute.
    void setAttribute(const std::string& name, double v);
    void setAttribute(const std::string& name, const std::string& v);
    //- Overload so that string literals do not convert to double... or bool.
    void setAttribute(const std::string& name, const char* v) { setAttribute(name, std::string(v)); }

    //- A root attribute written with the next flush that writes samples (run totals that
    //  change with every sample, without a rewrite of the file of their own); the last
    //  value staged for a name wins.
    void stageAttribute(const std::string& name, double v);

    //- Append one sample (held in memory until flush); values has nCells*nMoments
    //  entries, cell-major (values[cell*nMoments + k]); otherwise std::invalid_argument.
    void append(double time, const std::vector<double>& values);

    //- Write the samples held in memory to the file (atomically, see above).
    void flush();

    //- Samples on disk and held in memory.
    std::size_t nSamples() const;
    std::size_t nCells() const;
    int nMoments() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//- Reads a whole file written by MomentSeriesWriter into memory.
class MomentSeriesReader {
public:
    explicit MomentSeriesReader(const std::string& path);
    ~MomentSeriesReader();
    MomentSeriesReader(MomentSeriesReader&&) noexcept;
    MomentSeriesReader& operator=(MomentSeriesReader&&) noexcept;
    MomentSeriesReader(const MomentSeriesReader&) = delete;
    MomentSeriesReader& operator=(const MomentSeriesReader&) = delete;

    std::size_t nSamples() const;
    std::size_t nCells() const;
    int nMoments() const;
    const std::vector<double>& times() const;
    const std::vector<std::array<double, 3>>& cellCentres() const;
    //- Throws std::out_of_range for an index outside the file.
    double value(std::size_t sample, std::size_t cell, int k) const;
    //- Throw std::invalid_argument when the attribute is missing or of the other kind.
    double numberAttribute(const std::string& name) const;
    std::string stringAttribute(const std::string& name) const;
    bool hasAttribute(const std::string& name) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace coag

#endif
