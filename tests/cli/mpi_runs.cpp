// Runs on several MPI processes (issue 16, docs/mpi.md): how they are started (--np, P mpi_nbcpu,
// mpirun by hand), what rank 0 alone writes, the distributed solution against the one-process one
// (refined ssnv511e, N = 101, read back from the MED files) and bad input ending as on one process.
// Every run is bounded by `timeout`: a hung process fails the test instead of blocking it.
#include <gtest/gtest.h>
#include <sys/mount.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "med_io/MedResultReader.hpp"
#include "med_io/MedWriter.hpp"
#include "parser_run.hpp"
#include "scenes/Ssnv511Mesh.hpp"

namespace fs = std::filesystem;
using namespace ma::test;

namespace {

const std::string kSource = MINIASTER_SOURCE_DIR;
const std::string kShared = MINIASTER_SHARED_DIR;
const std::string kTimeout = "timeout 300 ";
const std::string kMpirun =
    "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 300 mpirun --quiet --oversubscribe ";

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

// The verdict and kind of every TEST line of a .resu, in order.
std::vector<std::string> verdicts(const std::string& resu) {
    std::vector<std::string> out;
    static const std::regex line("(^|\n) *(OK|NOOK) +([A-Z_]+) ");
    for (auto it = std::sregex_iterator(resu.begin(), resu.end(), line); it != std::sregex_iterator(); ++it)
        out.push_back((*it)[2].str() + " " + (*it)[3].str());
    return out;
}

std::vector<std::string> sortedFiles(const RunResult& r) {
    auto files = r.files();
    std::sort(files.begin(), files.end());
    return files;
}

// The lines of the output that start with "<F>" (the failure paragraphs).
std::string failures(const std::string& output) {
    std::string out;
    std::istringstream in(output);
    for (std::string l; std::getline(in, l);)
        if (l.rfind("<F>", 0) == 0) out += l + "\n";
    return out;
}

// Runs `input` in dir/np1 and dir/np2 with 1 and 2 processes (env before the command).
std::pair<RunResult, RunResult> onOneAndTwo(const fs::path& dir, const std::string& input, const std::string& extra,
                                            const std::string& env = "") {
    fs::create_directories(dir / "np1");
    fs::create_directories(dir / "np2");
    return {runMiniaster(dir / "np1", input, extra + " --np 1", env + kTimeout),
            runMiniaster(dir / "np2", input, extra + " --np 2", env + kTimeout)};
}

void expectSameEnd(const RunResult& one, const RunResult& two, int status) {
    EXPECT_EQ(one.status, status) << one.output;
    EXPECT_EQ(two.status, status) << two.output;
    EXPECT_EQ(failures(two.output), failures(one.output));
    EXPECT_EQ(sortedFiles(two), sortedFiles(one));
    EXPECT_EQ(verdicts(two.file("out/t.resu")), verdicts(one.file("out/t.resu")));
}

// xfem_quad4_n7 (an X-FEM case with a MED output) on 2 processes: the TEST results of one
// process, rank 0's files only (no temporary, no stray file), the processes in the header.
TEST(MpiRuns, TwoProcessesWriteWhatOneWrites) {
    const auto [one, two] = onOneAndTwo(freshDir(), kSource + "/astest/xfem_quad4_n7.export", "");
    ASSERT_EQ(one.status, 0) << one.output;
    EXPECT_EQ(two.status, 0) << two.output;
    const std::string mess = two.file("out/xfem_quad4_n7.mess");
    EXPECT_NE(mess.find("  MPI processes: 2\n"), std::string::npos) << mess;
    EXPECT_NE(one.file("out/xfem_quad4_n7.mess").find("  MPI processes: 1\n"), std::string::npos);
    EXPECT_TRUE(std::regex_search(mess, std::regex("cells partitioned over 2 processes \\(METIS_PartMeshDual.*\\): "
                                                   "[0-9]+ [0-9]+ elements per process")))
        << mess;
    EXPECT_NE(mess.find("in distributed triplets from 2 processes (ICNTL(18)=3)"), std::string::npos);
    const auto expected = verdicts(one.file("out/xfem_quad4_n7.resu"));
    EXPECT_GE(expected.size(), 4u);
    EXPECT_EQ(verdicts(two.file("out/xfem_quad4_n7.resu")), expected);
    EXPECT_EQ(sortedFiles(two), sortedFiles(one));
    EXPECT_EQ(sortedFiles(two),
              (std::vector<std::string>{"xfem_quad4_n7.mess", "xfem_quad4_n7.resu", "xfem_quad4_n7.rmed"}));
    // The header once, from rank 0 only.
    EXPECT_EQ(two.output.find("MPI processes: 2"), two.output.rfind("MPI processes: 2")) << two.output;
}

// P mpi_nbcpu in the .export starts the processes; --np on the command line wins; mpirun by hand
// works, and a --np that contradicts it is refused.
TEST(MpiRuns, ProcessCountFromExportCommandLineAndMpirun) {
    auto dir = freshDir();
    writeText(dir / "t.export", "P mpi_nbcpu 2\nF comm " + kSource + "/astest/fe_patch_quad4.comm D 1\nF mmed " +
                                    kSource + "/astest/fe_patch_quad4.mmed D 20\n");
    auto r = runMiniaster(dir, "t.export", "", kTimeout);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.file("out/t.mess").find("  MPI processes: 2\n"), std::string::npos);
    r = runMiniaster(dir, "t.export", "--np 1", kTimeout);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.file("out/t.mess").find("  MPI processes: 1\n"), std::string::npos);

    r = runMiniaster(dir, "t.export", "", kMpirun + "-np 3");
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.file("out/t.mess").find("  MPI processes: 3\n"), std::string::npos);
    r = runMiniaster(dir, "t.export", "--np 2", kMpirun + "-np 3");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("miniaster: --np 2: this run has 3 MPI process(es) (mpirun -np 3)"), std::string::npos)
        << r.output;

    writeText(dir / "bad.export", "P mpi_nbcpu 0\nF comm " + kSource + "/astest/fe_patch_quad4.comm D 1\n");
    r = runMiniaster(dir, "bad.export", "", kTimeout);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("bad.export, line 1: 'mpi_nbcpu' must be a number of processes from 1 to 4096"),
              std::string::npos)
        << r.output;
}

// Bad input on 2 processes ends as on one: the same paragraph, exit status and files, no hung
// process (timeout), no temporary. A missing group, a singular system, a NOOK, and a failure of
// rank 0 alone (its MED write: the other process has nothing to write and must stop with it).
TEST(MpiRuns, BadInputEndsAsOnOneProcess) {
    const std::string patch = readAll(kSource + "/astest/fe_patch_quad4.comm");
    const std::string mesh = "--mesh '" + kSource + "/astest/fe_patch_quad4.mmed'";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"AFFE_CHAR_MECA (t.comm, line 49): DDL_IMPO[1]/GROUP_MA: the mesh MA has no cell group 'LX'",
         replaced(patch, "_F(GROUP_MA='LG', DX=0.0)", "_F(GROUP_MA='LX', DX=0.0)")},
        {"MECA_STATIQUE (t.comm, line 53): numerical failure: singular system: MUMPS found 1 null pivot(s)",
         replaced(patch, "DDL_IMPO=(_F(GROUP_MA='LG', DX=0.0), _F(GROUP_MA='LB', DY=0.0))",
                  "DDL_IMPO=(_F(GROUP_MA='LG', DX=0.0),)")},
    };
    for (const auto& [cause, comm] : cases) {
        SCOPED_TRACE(cause);
        const auto dir = freshDir();
        for (const char* np : {"np1", "np2"}) {
            fs::create_directories(dir / np);
            writeText(dir / np / "t.comm", comm);
        }
        const auto [one, two] = onOneAndTwo(dir, "t.comm", mesh);
        expectSameEnd(one, two, 1);
        EXPECT_NE(failures(two.output).find("<F> <ERROR> " + cause), std::string::npos) << two.output;
        EXPECT_EQ(sortedFiles(two), std::vector<std::string>{"t.mess"});
        EXPECT_NE(two.file("out/t.mess").find("--- DIAGNOSTIC JOB : <F>_ERROR"), std::string::npos);
    }

    // A NOOK: exit 2, the same TEST lines.
    {
        const auto [one, two] = onOneAndTwo(freshDir(), kSource + "/astest/tables_nook.export", "");
        EXPECT_EQ(one.status, 2) << one.output;
        EXPECT_EQ(two.status, 2) << two.output;
        EXPECT_EQ(verdicts(two.file("out/tables_nook.resu")), verdicts(one.file("out/tables_nook.resu")));
        const auto lines = verdicts(one.file("out/tables_nook.resu"));
        EXPECT_NE(std::find(lines.begin(), lines.end(), "NOOK ANALYTIQUE"), lines.end());
    }
}

// Rank 0's MED write fails (a full disk: a tmpfs of 200 kB nearly filled as the output folder): the
// other process has nothing to write and must stop with rank 0's error, as one process does.
TEST(MpiRuns, RankZeroWriteFailureStopsEveryProcess) {
    const auto dir = freshDir();
    for (const char* np : {"np1", "np2"}) {
        fs::create_directories(dir / np / "out");
        if (::mount("tmpfs", (dir / np / "out").c_str(), "tmpfs", 0, "size=200k") != 0)
            GTEST_SKIP() << "cannot mount a tmpfs here (needs root)";
        std::ofstream(dir / np / "out/filler", std::ios::binary) << std::string(175000, '\0');
    }
    const auto [one, two] = onOneAndTwo(dir, kSource + "/astest/xfem_quad4_n7.export", "");
    const auto files = std::make_pair(sortedFiles(one), sortedFiles(two));
    bool temporary = false;
    for (const char* np : {"np1", "np2"}) {
        for (const auto& e : fs::directory_iterator(dir / np / "out"))
            temporary = temporary || e.path().filename().string().find(".miniaster-tmp.") != std::string::npos;
        ::umount((dir / np / "out").c_str());
    }
    EXPECT_EQ(one.status, 1) << one.output;
    EXPECT_EQ(two.status, 1) << two.output;
    EXPECT_NE(failures(two.output).find("<F> <ERROR> IMPR_RESU (xfem_quad4.comm, line 52): MED file '"),
              std::string::npos)
        << two.output;
    EXPECT_NE(two.output.find("No space left on device"), std::string::npos) << two.output;
    EXPECT_EQ(std::regex_replace(failures(two.output), std::regex("/np2/"), "/np1/"), failures(one.output));
    EXPECT_EQ(files.second, files.first);
    EXPECT_EQ(std::count(files.second.begin(), files.second.end(), "xfem_quad4_n7.rmed"), 0);
    EXPECT_FALSE(temporary);
}

// Processes whose command line names `folder` (a run of this test left behind).
int processesIn(const fs::path& folder) {
    int n = 0;
    for (const auto& e : fs::directory_iterator("/proc")) {
        const std::string cmdline = readAll(e.path() / "cmdline");
        n += cmdline.find(folder.string()) != std::string::npos;
    }
    return n;
}

// P time_limit and SIGTERM on 2 processes: rank 0 writes the paragraph and the TEST lines done so
// far, as one process does; no process is left.
TEST(MpiRuns, TimeLimitAndSignalStopEveryProcess) {
    const auto dir = freshDir();
    writeText(dir / "t.comm",
              replaced(readAll(kSource + "/astest/tables_chain.comm"), "\nFIN()", "\nwhile True: pass"));
    writeText(dir / "t.export",
              "P time_limit 2\nF comm t.comm D 1\nF mmed " + kSource + "/astest/tables_chain.mmed D 20\n");
    writeText(dir / "k.export", "F comm t.comm D 1\nF mmed " + kSource + "/astest/tables_chain.mmed D 20\n");
    auto r = runMiniaster(dir, "t.export", "--np 2", kTimeout);
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.file("out/t.mess").find("<F> <TIME_LIMIT> (t.comm, in the Python code after the command of line"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.file("out/t.resu").find(" OK "), std::string::npos);

    // SIGTERM to the run (the launcher, mpirun's parent: it forwards it), 3 s after its start.
    EXPECT_EQ(runThenTerminate(dir, quotedBinary() + " run k.export --np 2 --out-dir out", 3), 1)
        << readAll(dir / "run.log");
    const std::string mess = r.file("out/k.mess");
    EXPECT_NE(mess.find("<F> <INTERRUPTED> (t.comm, in the Python code after the command of line"), std::string::npos)
        << readAll(dir / "run.log");
    EXPECT_NE(mess.find("--- DIAGNOSTIC JOB : <F>_INTERRUPTED"), std::string::npos);
    EXPECT_EQ(processesIn(dir), 0);
    for (const auto& e : fs::recursive_directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".miniaster-tmp."), std::string::npos) << e.path();
}

// The refined ssnv511e scene of ../shared/bench (X-FEM junction, contact on the three interfaces)
// on a 101 x 101 QUAD4 mesh, on 1, 2 and 4 processes (4 oversubscribed on a 2-core machine): every
// component of the displacement field (DEPL, enrichments included) read back from the MED result
// agrees with the one-process field to 1e-10 relative (of its largest value), SIEF_ELGA to 1e-9,
// with the same number of contact iterations; each field is the exact solution to 1e-10 (POST_ERREUR
// lines).
TEST(MpiRuns, RefinedSsnv511eSameFieldOnTwoAndFourProcesses) {
    const auto dir = freshDir();
    ma::Ssnv511MeshOptions o;
    o.divisions = 101;
    {
        ma::med::MedWriter w((dir / "mesh.med").string(), false);
        w.writeMesh(*ma::buildSsnv511Mesh(o), "MAILLAGE");
        w.commit();
    }
    writeText(dir / "e.comm", replaced(readAll(kShared + "/bench/refined_e.comm"), "\nFIN()",
                                       "\nIMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU))\nFIN()"));
    writeText(dir / "e.export", "F comm e.comm D 1\nF mmed mesh.med D 20\nF rmed e.rmed R 80\n");
    std::vector<std::vector<double>> fields, stresses;
    std::vector<std::string> iterations;
    for (const char* np : {"1", "2", "4"}) {
        SCOPED_TRACE(std::string("--np ") + np);
        const auto out = dir / ("np" + std::string(np));
        fs::create_directories(out);
        auto r = runMiniaster(out, (dir / "e.export").string(), std::string("--np ") + np, kTimeout);
        ASSERT_EQ(r.status, 0) << r.output;
        const std::string mess = r.file("out/e.mess");
        std::smatch m;
        ASSERT_TRUE(
            std::regex_search(mess, m, std::regex("increment 1 \\(INST 1\\): ([0-9]+) contact iteration\\(s\\)")));
        iterations.push_back(m[1]);
        for (const char* norm : {"ENERGIE", "L2 DU DEPLACEMENT"}) {
            ASSERT_TRUE(std::regex_search(
                mess, m, std::regex(std::string("ERREUR EN NORME ") + norm + ".*ERREUR RELATIVE = ([-0-9.e+]+)")));
            EXPECT_LT(std::stod(m[1]), 1e-10) << norm;
        }
        const auto results = ma::med::readResults((out / "out/e.rmed").string());
        ASSERT_FALSE(results.empty());
        std::vector<double> values, points;
        for (const auto& f : results.front().fields)
            for (const auto& step : f.steps) {
                if (f.name.find("DEPL") != std::string::npos && step.nodal)
                    values.insert(values.end(), step.nodal->values.begin(), step.nodal->values.end());
                if (f.name.find("SIEF_ELGA") != std::string::npos && step.cellPoints)
                    points.insert(points.end(), step.cellPoints->values.begin(), step.cellPoints->values.end());
            }
        ASSERT_GT(values.size(), size_t(2 * 102 * 102));
        ASSERT_GT(points.size(), size_t(4 * 4 * 101 * 101));  // SIXX SIYY SIZZ SIXY at 4 points a cell at least
        fields.push_back(values);
        stresses.push_back(points);
    }
    // The largest |field k - field 0| relative to the largest |field 0|, for K = 2 and 4 processes.
    auto relativeDifferences = [](const std::vector<std::vector<double>>& runs) {
        double largest = 0.0;
        for (double v : runs[0]) largest = std::max(largest, std::abs(v));
        std::vector<double> out;
        for (size_t k = 1; k < runs.size(); ++k) {
            EXPECT_EQ(runs[k].size(), runs[0].size());
            double difference = 0.0;
            for (size_t i = 0; i < std::min(runs[k].size(), runs[0].size()); ++i)
                difference = std::max(difference, std::abs(runs[k][i] - runs[0][i]));
            out.push_back(difference / largest);
        }
        return std::pair{largest, out};
    };
    const auto [largest, displacements] = relativeDifferences(fields);
    EXPECT_GT(largest, 0.07);  // |u| = 0.0715 + 0.0104 * 5 at the top right corner
    // The stresses, each process computing its own elements' points and gathering the others': the
    // one-process field to round-off (a misplaced element's points would differ by the stress itself).
    const std::vector<double> stressDifferences = relativeDifferences(stresses).second;
    for (size_t k = 1; k < fields.size(); ++k) {
        EXPECT_LT(displacements[k - 1], 1e-10) << "K = " << (k == 1 ? 2 : 4);
        EXPECT_LT(stressDifferences[k - 1], 1e-9) << "K = " << (k == 1 ? 2 : 4);
        std::printf("refined ssnv511e N=101, K=%d: max |u_K - u_1| / max |u_1| = %.3e, SIEF_ELGA %.3e\n",
                    k == 1 ? 2 : 4, displacements[k - 1], stressDifferences[k - 1]);
        EXPECT_EQ(iterations[k], iterations[0]);
    }
}

}  // namespace
