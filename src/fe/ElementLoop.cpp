#include "fe/ElementLoop.hpp"

#include "fe/Parallel.hpp"

namespace ma {

int elementWorkers(size_t nElements) {
    return static_cast<int>(std::min<size_t>(workerCount(), std::max<size_t>(1, nElements / kElementBatch)));
}

}  // namespace ma
