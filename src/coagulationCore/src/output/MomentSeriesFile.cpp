// coagulationFoam core. Copyright (C) 2025-2026 the coagulationFoam authors
// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "coagulation/output/MomentSeriesFile.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

namespace coag {

namespace {

[[noreturn]] void rethrow(const char* where, const H5::Exception& e)
{
    throw std::runtime_error(std::string("coag::") + where + ": HDF5 error in "
                             + e.getFuncName() + ": " + e.getDetailMsg());
}

void silenceHdf5()
{
    H5::Exception::dontPrint();
}

} // namespace

// ---------------------------------------------------------------------------- writer

struct MomentSeriesWriter::Impl {
    std::string path;
    std::size_t nCells = 0;
    int nMoments = 0;
    std::size_t nOnDisk = 0;
    std::vector<double> pendingTimes;
    std::vector<double> pendingValues;
    std::map<std::string, double> pendingAttributes;

    static void writeAttribute(H5::H5File& file, const std::string& name, double v)
    {
        H5::Group root = file.openGroup("/");
        if (root.attrExists(name)) root.removeAttr(name);
        H5::Attribute a =
            root.createAttribute(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace(H5S_SCALAR));
        a.write(H5::PredType::NATIVE_DOUBLE, &v);
    }

    //- Apply change to the file in memory (HDF5's core driver), write the image to
    //  <path>.tmp with plain stdio, then rename it over the file. HDF5 does no file I/O of
    //  its own, so an I/O failure (a full disk) is met here, where the file is untouched;
    //  it throws std::runtime_error naming where.
    template<class Change>
    void modify(const char* where, Change&& change, bool create = false)
    {
        const std::string tmp = path + ".tmp";
        std::vector<char> image;
        try {
            H5::FileAccPropList fapl;
            fapl.setCore(1 << 20, false);
            H5::H5File file(path, create ? H5F_ACC_TRUNC : H5F_ACC_RDWR,
                            H5::FileCreatPropList::DEFAULT, fapl);
            change(file);
            file.flush(H5F_SCOPE_GLOBAL);
            const ssize_t size = H5Fget_file_image(file.getId(), nullptr, 0);
            if (size < 0) throw std::runtime_error("H5Fget_file_image failed");
            image.resize(static_cast<std::size_t>(size));
            if (H5Fget_file_image(file.getId(), image.data(), image.size()) != size) {
                throw std::runtime_error("H5Fget_file_image failed");
            }
            file.close();
        } catch (const H5::Exception& e) {
            rethrow(where, e);
        }

        std::FILE* out = std::fopen(tmp.c_str(), "wb");
        bool ok = out != nullptr;
        int error = ok ? 0 : errno;
        if (ok) {
            ok = std::fwrite(image.data(), 1, image.size(), out) == image.size();
            if (!ok) error = errno;
            if (std::fclose(out) != 0 && ok) {
                ok = false;
                error = errno;
            }
        }
        if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
            ok = false;
            error = errno;
        }
        if (!ok) {
            std::remove(tmp.c_str());
            throw std::runtime_error(std::string("coag::") + where + ": cannot write "
                                     + std::to_string(image.size()) + " bytes to " + tmp
                                     + ": " + std::strerror(error)
                                     + "; " + path + " is left as it was");
        }
    }
};

MomentSeriesWriter::MomentSeriesWriter(const std::string& path,
                                       const std::vector<std::array<double, 3>>& cellCentres,
                                       int nMoments)
    : impl_(std::make_unique<Impl>())
{
    if (nMoments <= 0) {
        throw std::invalid_argument("coag::MomentSeriesWriter: nMoments must be > 0");
    }
    silenceHdf5();
    Impl& d = *impl_;
    d.path = path;
    d.nCells = cellCentres.size();
    d.nMoments = nMoments;
    d.modify("MomentSeriesWriter", [&](H5::H5File& file) {
        // /cellCentres
        {
            const hsize_t dims[2] = {d.nCells, 3};
            H5::DataSpace space(2, dims);
            H5::DataSet ds = file.createDataSet("cellCentres", H5::PredType::NATIVE_DOUBLE, space);
            if (d.nCells > 0) ds.write(cellCentres.data(), H5::PredType::NATIVE_DOUBLE);
        }
        // /time
        {
            const hsize_t dims[1] = {0};
            const hsize_t maxDims[1] = {H5S_UNLIMITED};
            const hsize_t chunk[1] = {1024};
            H5::DataSpace space(1, dims, maxDims);
            H5::DSetCreatPropList plist;
            plist.setChunk(1, chunk);
            file.createDataSet("time", H5::PredType::NATIVE_DOUBLE, space, plist);
        }
        // /moments: chunks of about 64k values, whole moment vectors per cell.
        {
            const hsize_t nm = static_cast<hsize_t>(nMoments);
            const hsize_t target = 65536;
            hsize_t chunkCells = std::max<hsize_t>(1, std::min<hsize_t>(d.nCells, target / nm));
            hsize_t chunkSamples =
                std::max<hsize_t>(1, std::min<hsize_t>(64, target / (chunkCells * nm)));
            const hsize_t dims[3] = {0, d.nCells, nm};
            const hsize_t maxDims[3] = {H5S_UNLIMITED, d.nCells > 0 ? d.nCells : H5S_UNLIMITED, nm};
            const hsize_t chunk[3] = {chunkSamples, chunkCells, nm};
            H5::DataSpace space(3, dims, maxDims);
            H5::DSetCreatPropList plist;
            plist.setChunk(3, chunk);
            file.createDataSet("moments", H5::PredType::NATIVE_DOUBLE, space, plist);
        }
    }, true);
}

MomentSeriesWriter::~MomentSeriesWriter()
{
    // What was appended since the last flush, if the file can still take it
    if (impl_) {
        try {
            flush();
        } catch (...) {
        }
    }
}

MomentSeriesWriter::MomentSeriesWriter(MomentSeriesWriter&&) noexcept = default;
MomentSeriesWriter& MomentSeriesWriter::operator=(MomentSeriesWriter&&) noexcept = default;

std::size_t MomentSeriesWriter::nSamples() const
{
    return impl_->nOnDisk + impl_->pendingTimes.size();
}
std::size_t MomentSeriesWriter::nCells() const { return impl_->nCells; }
int MomentSeriesWriter::nMoments() const { return impl_->nMoments; }

void MomentSeriesWriter::setAttribute(const std::string& name, double v)
{
    impl_->modify("MomentSeriesWriter::setAttribute",
                  [&](H5::H5File& file) { Impl::writeAttribute(file, name, v); });
}

void MomentSeriesWriter::stageAttribute(const std::string& name, double v)
{
    impl_->pendingAttributes[name] = v;
}

void MomentSeriesWriter::setAttribute(const std::string& name, const std::string& v)
{
    impl_->modify("MomentSeriesWriter::setAttribute", [&](H5::H5File& file) {
        H5::Group root = file.openGroup("/");
        if (root.attrExists(name)) root.removeAttr(name);
        H5::StrType type(H5::PredType::C_S1, std::max<std::size_t>(1, v.size()));
        H5::Attribute a = root.createAttribute(name, type, H5::DataSpace(H5S_SCALAR));
        a.write(type, v);
    });
}

void MomentSeriesWriter::append(double time, const std::vector<double>& values)
{
    Impl& d = *impl_;
    const std::size_t expected = d.nCells * static_cast<std::size_t>(d.nMoments);
    if (values.size() != expected) {
        std::ostringstream os;
        os << "coag::MomentSeriesWriter::append: expected " << expected
           << " values (nCells*nMoments), got " << values.size();
        throw std::invalid_argument(os.str());
    }
    d.pendingTimes.push_back(time);
    d.pendingValues.insert(d.pendingValues.end(), values.begin(), values.end());
}

void MomentSeriesWriter::flush()
{
    Impl& d = *impl_;
    if (d.pendingTimes.empty()) return;
    const hsize_t n = d.nOnDisk;
    const hsize_t k = d.pendingTimes.size();
    d.modify("MomentSeriesWriter::flush", [&](H5::H5File& file) {
        {
            H5::DataSet time = file.openDataSet("time");
            const hsize_t newDims[1] = {n + k};
            time.extend(newDims);
            H5::DataSpace space = time.getSpace();
            const hsize_t start[1] = {n};
            const hsize_t count[1] = {k};
            space.selectHyperslab(H5S_SELECT_SET, count, start);
            H5::DataSpace mem(1, count);
            time.write(d.pendingTimes.data(), H5::PredType::NATIVE_DOUBLE, mem, space);
        }
        {
            H5::DataSet moments = file.openDataSet("moments");
            const hsize_t nm = static_cast<hsize_t>(d.nMoments);
            const hsize_t newDims[3] = {n + k, d.nCells, nm};
            moments.extend(newDims);
            if (!d.pendingValues.empty()) {
                H5::DataSpace space = moments.getSpace();
                const hsize_t start[3] = {n, 0, 0};
                const hsize_t count[3] = {k, d.nCells, nm};
                space.selectHyperslab(H5S_SELECT_SET, count, start);
                H5::DataSpace mem(3, count);
                moments.write(d.pendingValues.data(), H5::PredType::NATIVE_DOUBLE, mem, space);
            }
        }
        for (const auto& a : d.pendingAttributes) Impl::writeAttribute(file, a.first, a.second);
    });
    d.nOnDisk += k;
    d.pendingTimes.clear();
    d.pendingValues.clear();
    d.pendingAttributes.clear();
}

// ---------------------------------------------------------------------------- reader

struct MomentSeriesReader::Impl {
    std::size_t nSamples = 0;
    std::size_t nCells = 0;
    int nMoments = 0;
    std::vector<double> times;
    std::vector<std::array<double, 3>> centres;
    std::vector<double> values;
    std::map<std::string, double> numbers;
    std::map<std::string, std::string> strings;
};

namespace {

void readAttribute(H5::Attribute& a, const std::string& name,
                   std::map<std::string, double>& numbers,
                   std::map<std::string, std::string>& strings)
{
    const H5T_class_t cls = a.getTypeClass();
    if (cls == H5T_STRING) {
        std::string s;
        a.read(a.getStrType(), s);
        // Fixed-length strings may carry padding NULs.
        const std::size_t end = s.find('\0');
        if (end != std::string::npos) s.resize(end);
        strings[name] = s;
    } else if (cls == H5T_FLOAT || cls == H5T_INTEGER) {
        if (a.getSpace().getSimpleExtentNpoints() == 1) {
            double v = 0.0;
            a.read(H5::PredType::NATIVE_DOUBLE, &v);
            numbers[name] = v;
        }
    }
}

} // namespace

MomentSeriesReader::MomentSeriesReader(const std::string& path)
    : impl_(std::make_unique<Impl>())
{
    silenceHdf5();
    Impl& d = *impl_;
    try {
        H5::H5File file(path, H5F_ACC_RDONLY);
        {
            H5::DataSet ds = file.openDataSet("cellCentres");
            H5::DataSpace sp = ds.getSpace();
            hsize_t dims[2] = {0, 0};
            if (sp.getSimpleExtentNdims() != 2) throw std::runtime_error("bad /cellCentres rank");
            sp.getSimpleExtentDims(dims);
            if (dims[1] != 3) throw std::runtime_error("bad /cellCentres shape");
            d.nCells = dims[0];
            d.centres.resize(d.nCells);
            if (d.nCells > 0) ds.read(d.centres.data(), H5::PredType::NATIVE_DOUBLE);
        }
        {
            H5::DataSet ds = file.openDataSet("time");
            H5::DataSpace sp = ds.getSpace();
            hsize_t dims[1] = {0};
            if (sp.getSimpleExtentNdims() != 1) throw std::runtime_error("bad /time rank");
            sp.getSimpleExtentDims(dims);
            d.nSamples = dims[0];
            d.times.resize(d.nSamples);
            if (d.nSamples > 0) ds.read(d.times.data(), H5::PredType::NATIVE_DOUBLE);
        }
        {
            H5::DataSet ds = file.openDataSet("moments");
            H5::DataSpace sp = ds.getSpace();
            hsize_t dims[3] = {0, 0, 0};
            if (sp.getSimpleExtentNdims() != 3) throw std::runtime_error("bad /moments rank");
            sp.getSimpleExtentDims(dims);
            if (dims[0] != d.nSamples || dims[1] != d.nCells) {
                throw std::runtime_error("/moments shape does not match /time and /cellCentres");
            }
            d.nMoments = static_cast<int>(dims[2]);
            d.values.resize(dims[0] * dims[1] * dims[2]);
            if (!d.values.empty()) ds.read(d.values.data(), H5::PredType::NATIVE_DOUBLE);
        }
        {
            H5::Group root = file.openGroup("/");
            const int n = root.getNumAttrs();
            for (int i = 0; i < n; ++i) {
                H5::Attribute a = root.openAttribute(static_cast<unsigned>(i));
                readAttribute(a, a.getName(), d.numbers, d.strings);
            }
        }
    } catch (const H5::Exception& e) {
        rethrow(("MomentSeriesReader('" + path + "')").c_str(), e);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error("coag::MomentSeriesReader('" + path + "'): " + e.what());
    }
}

MomentSeriesReader::~MomentSeriesReader() = default;
MomentSeriesReader::MomentSeriesReader(MomentSeriesReader&&) noexcept = default;
MomentSeriesReader& MomentSeriesReader::operator=(MomentSeriesReader&&) noexcept = default;

std::size_t MomentSeriesReader::nSamples() const { return impl_->nSamples; }
std::size_t MomentSeriesReader::nCells() const { return impl_->nCells; }
int MomentSeriesReader::nMoments() const { return impl_->nMoments; }
const std::vector<double>& MomentSeriesReader::times() const { return impl_->times; }
const std::vector<std::array<double, 3>>& MomentSeriesReader::cellCentres() const
{
    return impl_->centres;
}

double MomentSeriesReader::value(std::size_t sample, std::size_t cell, int k) const
{
    const Impl& d = *impl_;
    if (sample >= d.nSamples || cell >= d.nCells || k < 0 || k >= d.nMoments) {
        std::ostringstream os;
        os << "coag::MomentSeriesReader::value: index (" << sample << ", " << cell << ", " << k
           << ") outside [" << d.nSamples << "][" << d.nCells << "][" << d.nMoments << "]";
        throw std::out_of_range(os.str());
    }
    return d.values[(sample * d.nCells + cell) * static_cast<std::size_t>(d.nMoments)
                    + static_cast<std::size_t>(k)];
}

bool MomentSeriesReader::hasAttribute(const std::string& name) const
{
    return impl_->numbers.count(name) > 0 || impl_->strings.count(name) > 0;
}

double MomentSeriesReader::numberAttribute(const std::string& name) const
{
    const auto it = impl_->numbers.find(name);
    if (it == impl_->numbers.end()) {
        throw std::invalid_argument("coag::MomentSeriesReader::numberAttribute: no numeric "
                                    "attribute '" + name + "'");
    }
    return it->second;
}

std::string MomentSeriesReader::stringAttribute(const std::string& name) const
{
    const auto it = impl_->strings.find(name);
    if (it == impl_->strings.end()) {
        throw std::invalid_argument("coag::MomentSeriesReader::stringAttribute: no string "
                                    "attribute '" + name + "'");
    }
    return it->second;
}

} // namespace coag
