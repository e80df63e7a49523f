#include "parser/PeerWatch.hpp"

#include <fmt/format.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <sstream>

#include "core/Mpi.hpp"
#include "core/ProcessStat.hpp"

namespace ma {

namespace {

// The exit status of an ended process that its parent (mpirun) has not reaped yet: field 52 of
// /proc/PID/stat, in waitpid's form. Nothing once reaped (or for a live process).
std::optional<std::string> exitStatusOf(int pid) {
    const auto text = processStatFields(pid);
    if (!text) return std::nullopt;
    std::istringstream fields(*text);
    std::string field, state;
    fields >> state;  // field 3
    for (int k = 4; k <= 52 && fields >> field; ++k) {}
    if (state != "Z" || field.empty()) return std::nullopt;
    const int raw = std::atoi(field.c_str());
    if ((raw & 0x7f) == 0) return fmt::format("exit status {}", (raw >> 8) & 0xff);
    return fmt::format("signal {} ({})", raw & 0x7f, strsignal(raw & 0x7f));
}

}  // namespace

PeerWatch::PeerWatch() {
    // Rank 0 watches every other process; rank 1 watches rank 0 (and then ends its .mess).
    if (!mpi::running() || mpi::rank() > 1) return;
    const auto& pids = mpi::peersOnThisMachine();
    for (int r = 0; r < int(pids.size()); ++r) {
        if (pids[size_t(r)] <= 0 || (!mpi::isRoot() && r != 0)) continue;
        const int fd = int(::syscall(SYS_pidfd_open, pids[size_t(r)], 0));
        if (fd >= 0) peers_.push_back({r, pids[size_t(r)], fd});
    }
}

PeerWatch::~PeerWatch() {
    for (const auto& p : peers_) ::close(p.fd);
}

void PeerWatch::addTo(std::vector<pollfd>& fds) const {
    for (const auto& p : peers_) fds.push_back({p.fd, POLLIN, 0});
}

std::optional<std::string> PeerWatch::endedPeer() const {
    for (const auto& p : peers_) {
        pollfd f{p.fd, POLLIN, 0};
        if (::poll(&f, 1, 0) <= 0 || !(f.revents & POLLIN)) continue;
        const auto status = exitStatusOf(p.pid);
        return fmt::format("MPI process {} of {} (pid {}{})", p.rank, mpi::size(), p.pid,
                           status ? ", " + *status : std::string());
    }
    return std::nullopt;
}

}  // namespace ma
