// SPDX-License-Identifier: GPL-3.0-or-later (see COPYING)
#include "TestHelpers.hpp"

#include <csignal>
#include <filesystem>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace coagtest;

namespace {

std::string tempFile(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / "coagulationCoreTests";
    std::filesystem::create_directories(dir);
    const auto p = dir / name;
    std::filesystem::remove(p);
    return p.string();
}

} // namespace

TEST(MomentSeriesFile, RoundTripWithSeveralAppends)
{
    const std::string path = tempFile("roundTrip.h5");
    const std::vector<std::array<double, 3>> centres{{0.1, 0.2, 0.3}, {1.1, 1.2, 1.3}, {2.5, 0, -1}};
    const int nm = 4;
    auto value = [](std::size_t s, std::size_t c, int k) { return 1000.0 * s + 10.0 * c + k + 0.25; };
    {
        MomentSeriesWriter w(path, centres, nm);
        w.setAttribute("algorithm", "SWA");
        w.setAttribute("K0", 1e-5);
        w.setAttribute("K0", 2e-5);  // overwrite
        w.setAttribute("empty", std::string());
        for (std::size_t s = 0; s < 7; ++s) {
            std::vector<double> v(centres.size() * nm);
            for (std::size_t c = 0; c < centres.size(); ++c)
                for (int k = 0; k < nm; ++k) v[c * nm + static_cast<std::size_t>(k)] = value(s, c, k);
            w.append(0.5 * double(s), v);
            if (s == 3) w.flush();
        }
        EXPECT_EQ(w.nSamples(), 7u);
        EXPECT_THROW(w.append(9.0, std::vector<double>(5)), std::invalid_argument);
    }
    MomentSeriesReader r(path);
    EXPECT_EQ(r.nSamples(), 7u);
    EXPECT_EQ(r.nCells(), 3u);
    EXPECT_EQ(r.nMoments(), nm);
    ASSERT_EQ(r.times().size(), 7u);
    for (std::size_t s = 0; s < 7; ++s) EXPECT_EQ(r.times()[s], 0.5 * double(s));
    for (std::size_t c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i) EXPECT_EQ(r.cellCentres()[c][i], centres[c][i]);
    for (std::size_t s = 0; s < 7; ++s)
        for (std::size_t c = 0; c < 3; ++c)
            for (int k = 0; k < nm; ++k) EXPECT_EQ(r.value(s, c, k), value(s, c, k));
    EXPECT_EQ(r.stringAttribute("algorithm"), "SWA");
    EXPECT_EQ(r.numberAttribute("K0"), 2e-5);
    EXPECT_EQ(r.stringAttribute("empty"), "");
    EXPECT_TRUE(r.hasAttribute("algorithm"));
    EXPECT_FALSE(r.hasAttribute("nothing"));
    EXPECT_THROW(r.numberAttribute("algorithm"), std::invalid_argument);
    EXPECT_THROW(r.stringAttribute("missing"), std::invalid_argument);
    EXPECT_THROW(r.value(7, 0, 0), std::out_of_range);
    EXPECT_THROW(r.value(0, 3, 0), std::out_of_range);
    EXPECT_THROW(r.value(0, 0, 4), std::out_of_range);
}

// Staged attributes go to the file with the next flush of samples, the last value staged
TEST(MomentSeriesFile, StagedAttributesWrittenWithTheSamples)
{
    const std::string path = tempFile("staged.h5");
    const std::vector<std::array<double, 3>> centres{{0, 0, 0}};
    {
        MomentSeriesWriter w(path, centres, 1);
        w.stageAttribute("coagulations", 10);
        w.append(0.0, {1.0});
        w.flush();
        EXPECT_EQ(MomentSeriesReader(path).numberAttribute("coagulations"), 10);
        w.stageAttribute("coagulations", 20);
        w.stageAttribute("coagulations", 30);
        w.stageAttribute("fictitious", 5);
        EXPECT_FALSE(MomentSeriesReader(path).hasAttribute("fictitious"));
        w.append(1.0, {2.0});
        w.flush();
    }
    MomentSeriesReader r(path);
    EXPECT_EQ(r.numberAttribute("coagulations"), 30);
    EXPECT_EQ(r.numberAttribute("fictitious"), 5);
    EXPECT_EQ(r.nSamples(), 2u);
}

TEST(MomentSeriesFile, ManyCellsAndSamplesCrossChunks)
{
    const std::string path = tempFile("large.h5");
    const std::size_t nCells = 20000;
    std::vector<std::array<double, 3>> centres(nCells);
    for (std::size_t c = 0; c < nCells; ++c) centres[c] = {double(c), 0.0, 0.0};
    {
        MomentSeriesWriter w(path, centres, 2);
        for (int s = 0; s < 70; ++s) {
            std::vector<double> v(2 * nCells);
            for (std::size_t i = 0; i < v.size(); ++i) v[i] = s * 1e6 + double(i);
            w.append(double(s), v);
        }
    }
    MomentSeriesReader r(path);
    ASSERT_EQ(r.nSamples(), 70u);
    ASSERT_EQ(r.nCells(), nCells);
    EXPECT_EQ(r.value(69, nCells - 1, 1), 69e6 + double(2 * nCells - 1));
    EXPECT_EQ(r.value(33, 1234, 0), 33e6 + 2468.0);
}

TEST(MomentSeriesFile, ZeroCellsIsAllowed)
{
    const std::string path = tempFile("empty.h5");
    {
        MomentSeriesWriter w(path, {}, 4);
        w.append(1.0, {});
        w.append(2.0, {});
    }
    MomentSeriesReader r(path);
    EXPECT_EQ(r.nCells(), 0u);
    EXPECT_EQ(r.nSamples(), 2u);
    EXPECT_EQ(r.times()[1], 2.0);
}

TEST(MomentSeriesFile, MissingFileThrows)
{
    EXPECT_THROW(MomentSeriesReader("/nonexistent/dir/file.h5"), std::runtime_error);
    EXPECT_THROW(MomentSeriesWriter("/nonexistent/dir/file.h5", {}, 4), std::runtime_error);
}

namespace {

//- One sample of 50 cells x 4 moments, every value s + 1
std::vector<double> sampleValues(int s)
{
    return std::vector<double>(200, double(s) + 1.0);
}

//- In a child process: 20 samples flushed, then body(writer); the child's exit code
int inChild(const std::string& path, const std::function<int(MomentSeriesWriter&)>& body)
{
    const pid_t pid = fork();
    if (pid == 0) {
        std::vector<std::array<double, 3>> centres(50, {0.0, 0.0, 0.0});
        MomentSeriesWriter w(path, centres, 4);
        w.setAttribute("algorithm", "SWA");
        for (int s = 0; s < 20; ++s) w.append(double(s), sampleValues(s));
        w.flush();
        _exit(body(w));
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return status;
}

void expectFlushedSamples(const std::string& path)
{
    MomentSeriesReader r(path);
    ASSERT_EQ(r.nSamples(), 20u);
    EXPECT_EQ(r.value(19, 49, 3), 20.0);
    EXPECT_EQ(r.stringAttribute("algorithm"), "SWA");
}

} // namespace

//- Killed after a flush, with more samples appended: the file holds every flushed sample.
TEST(MomentSeriesFile, SurvivesAKillBetweenFlushes)
{
    const std::string path = tempFile("killed.h5");
    const int status = inChild(path, [](MomentSeriesWriter& w) {
        // past HDF5's chunk cache, so that a writer that writes in place has to
        for (int s = 20; s < 20000; ++s) w.append(double(s), sampleValues(s));
        raise(SIGKILL);
        return 0;
    });
    ASSERT_TRUE(WIFSIGNALED(status));
    expectFlushedSamples(path);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}

//- A flush that meets a full disk (here a file size limit, EFBIG) throws and leaves the file
//  with every sample of the flushes before; the samples held are kept for another try.
TEST(MomentSeriesFile, SurvivesAFullDisk)
{
    const std::string path = tempFile("full.h5");
    const int status = inChild(path, [&path](MomentSeriesWriter& w) {
        signal(SIGXFSZ, SIG_IGN);
        rlimit limit{};
        limit.rlim_cur = limit.rlim_max = std::filesystem::file_size(path) + 1024;
        if (setrlimit(RLIMIT_FSIZE, &limit) != 0) return 10;
        for (int s = 20; s < 400; ++s) w.append(double(s), sampleValues(s));
        try {
            w.flush();
        } catch (const std::runtime_error&) {
            return w.nSamples() == 400 ? 0 : 13;
        }
        return 11;  // the flush did not fail
    });
    ASSERT_TRUE(WIFEXITED(status)) << "the child died of signal " << WTERMSIG(status);
    ASSERT_EQ(WEXITSTATUS(status), 0);
    expectFlushedSamples(path);
    EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
}
