// core/ProcessStat: the fields of /proc/PID/stat after the command name, for a live process, a
// zombie (its exit status, field 52, which rank 0 reads for a process that ended first) and a
// process that no longer exists (nothing, no exception).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <sstream>
#include <thread>

#include "core/ProcessStat.hpp"

namespace ma {
namespace {

std::vector<std::string> split(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string f; in >> f;) out.push_back(f);
    return out;
}

TEST(ProcessStat, LiveZombieAndGone) {
    const auto self = processStatFields(getpid());
    ASSERT_TRUE(self.has_value());
    const auto fields = split(*self);
    ASSERT_GE(fields.size(), 50u);
    EXPECT_EQ(fields[1], std::to_string(getppid()));  // field 4

    const pid_t child = fork();
    if (child == 0) _exit(5);
    // Not reaped yet: a zombie, whose field 52 is waitpid's status.
    const auto state = [&] {
        const auto f = split(processStatFields(child).value_or(""));
        return f.empty() ? std::string() : f[0];
    };
    for (int k = 0; k < 200 && state() != "Z"; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const auto zombie = split(processStatFields(child).value_or(""));
    ASSERT_GE(zombie.size(), 50u);
    EXPECT_EQ(zombie[0], "Z");
    EXPECT_EQ((std::stoi(zombie.back()) >> 8) & 0xff, 5);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_FALSE(processStatFields(child).has_value());
}

}  // namespace
}  // namespace ma
