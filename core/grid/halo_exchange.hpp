#pragma once
// Fills the ghost layers of a patch's arrays from the neighbouring patches (periodic images included).
// Domain-boundary ghosts are left to the boundary conditions.
#include <vector>

#include "field.hpp"

namespace chute {

class HaloExchange {
public:
    explicit HaloExchange(const Grid& grid) : grid_(grid) {}
    // x-direction first (owned rows), then y (all columns incl. x ghosts), so corners are filled too.
    void exchange(Field2D& f);
    void exchange(Velocity& vel) {
        exchange(vel.u);
        exchange(vel.v);
    }

private:
    const Grid& grid_;
    std::vector<double> send_lo_, send_hi_, recv_lo_, recv_hi_;
};

}  // namespace chute
