// Placeholder until the supervisor lands (issue 2): refuses to run rather than pretend.
#include "parser/Supervisor.hpp"

#include <cstdio>

namespace ma {

int supervisorMain(int, char**) {
    std::fprintf(stderr, "miniaster: the supervisor is not implemented yet\n");
    return 1;
}

}  // namespace ma
