// Bad MED input through the whole program: one clear error naming the file or group and the .comm
// line, exit status 1, no crash, no MED/HDF5 messages on stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>

#include "med_test_support.hpp"

namespace {

struct Run {
    int status;
    std::string mess;
    std::string stderrText;
};

Run runComm(const std::string& dir, const std::string& comm, const std::string& mesh) {
    std::ofstream(dir + "/case.comm") << comm;
    int rc = 0;
    ma::test::runCommand(std::string(MINIASTER_BINARY) + " run " + dir + "/case.comm --mesh '" + mesh + "' --out-dir " +
                             dir + " >" + dir + "/stdout.txt 2>" + dir + "/stderr.txt",
                         &rc);
    std::ifstream m(dir + "/case.mess"), e(dir + "/stderr.txt");
    std::stringstream ms, es;
    ms << m.rdbuf();
    es << e.rdbuf();
    return {WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, ms.str(), es.str()};
}

const char* kRead = "DEBUT()\nMA=LIRE_MAILLAGE(FORMAT='MED')\nFIN()\n";

}  // namespace

TEST(MedCli, BadMeshFilesAndGroupsStopTheRunWithStatus1) {
    const auto dir = ma::test::scratchDir("med_cli");
    const std::string missing = dir + "/absent.med";
    auto r = runComm(dir, kRead, missing);
    EXPECT_EQ(r.status, 1);
    // (the launcher checks --mesh itself; LIRE_MAILLAGE's own message is tested in test_med_commands)
    EXPECT_NE(r.mess.find(missing), std::string::npos) << r.mess;
    EXPECT_NE(r.mess.find("does not exist"), std::string::npos) << r.mess;

    const std::string text = dir + "/text.med";
    std::ofstream(text) << "not a MED file";
    r = runComm(dir, kRead, text);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.mess.find("line 2): file '" + text + "' is not a MED file: it is not in HDF5 format"),
              std::string::npos);

    const std::string truncated = dir + "/truncated.med";
    std::filesystem::copy_file(ma::test::astest("ssnv511h.mmed"), truncated);
    std::filesystem::resize_file(truncated, 9000);
    r = runComm(dir, kRead, truncated);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.mess.find("line 2): MED file '" + truncated + "' is damaged or truncated"), std::string::npos)
        << r.mess;
    EXPECT_EQ(r.stderrText.find("HDF5"), std::string::npos) << r.stderrText;
    EXPECT_EQ(r.stderrText.find("Erreur"), std::string::npos) << r.stderrText;

    r = runComm(dir, "DEBUT()\nMA=LIRE_MAILLAGE(FORMAT='MED',\n   NOM_MED='MAIL')\nFIN()\n",
                ma::test::astest("ssnv511a.mmed"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.mess.find("line 2): NOM_MED='MAIL': MED file"), std::string::npos) << r.mess;
    EXPECT_NE(r.mess.find("meshes in the file: 'MA'"), std::string::npos);

    r = runComm(dir,
                "DEBUT()\nMA=LIRE_MAILLAGE(FORMAT='MED')\nMA=DEFI_GROUP(reuse=MA, MAILLAGE=MA,\n"
                "   CREA_GROUP_NO=_F(GROUP_MA='SD'))\nIMPR_RESU(FORMAT='MED', RESU=_F(MAILLAGE=MA))\nFIN()\n",
                ma::test::astest("ssnv511a.mmed"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.mess.find("DEFI_GROUP (case.comm, line 3): CREA_GROUP_NO[1]/GROUP_MA: the mesh MA has no cell group "
                          "'SD'"),
              std::string::npos)
        << r.mess;
    EXPECT_FALSE(std::filesystem::exists(dir + "/fort.80"));  // the run stopped before IMPR_RESU
    std::filesystem::remove_all(dir);
}
