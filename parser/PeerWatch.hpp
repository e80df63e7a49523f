#pragma once
// Rank 0 watches the other processes of the run that share its machine (docs/mpi.md): one that
// ends before the run does (os._exit in the command file, a crash, a kill from outside) leaves
// no message of its own, and mpirun then ends the job with a bare SIGTERM. Seen here first, its
// rank and exit status are named in rank 0's .mess. Rank 1 watches rank 0 likewise: when rank 0
// ends so, rank 1 ends its .mess (parser/RunOutputs stopRunNow).
#include <optional>
#include <string>
#include <vector>

#include <poll.h>

namespace ma {

class PeerWatch {
public:
    // The other processes on this machine (none on one process or on another rank than 0).
    PeerWatch();
    ~PeerWatch();
    PeerWatch(const PeerWatch&) = delete;
    PeerWatch& operator=(const PeerWatch&) = delete;

    // Descriptors to poll (readable once the process has ended).
    void addTo(std::vector<pollfd>& fds) const;
    // The first watched process that has ended, in words ("MPI process 1 of 2 (pid 12, exit
    // status 5)"); nothing while all live.
    std::optional<std::string> endedPeer() const;

private:
    struct Peer {
        int rank, pid, fd;
    };
    std::vector<Peer> peers_;
};

}  // namespace ma
