#pragma once
// The water squeezed out between a block and the ground brakes the block's motion towards the ground, and the
// water that must fill the gap holds it back as it leaves. Chute's CFD shows it on every bed run: the study's
// block, arriving at its terminal speed, is slowed by 16 % over its last two block sizes, where a free-stream drag
// gives nothing (docs/validation.md, "Calibration for the study's block"). The lumped model carries it as a drag
// on the velocity normal to the ground that grows towards the ground:
//   F_n = -1/2 rho_f C_D A G(c) |v_n| v_n,   G(c) = strength exp(-c / (decay a)),
// c the clearance above the impact point, a the block size. `chute calibrate` fits strength and decay to the CFD's
// approach to the bed (calibration.hpp); the impact point is where the CFD's contact acts (a third of the block's
// size off the bed for the study's block), so the law belongs to the calibration's contact distance.
#include <algorithm>
#include <cmath>

namespace chute {

struct GroundEffect {
    double strength = 0.0;  // G at the impact point (0: no ground effect)
    double decay = 0.3;     // block sizes over which G falls by e
    bool active() const { return strength > 0.0; }
    double factor(double clearance, double size) const {
        return strength * std::exp(-std::max(clearance, 0.0) / (decay * size));
    }
};

}  // namespace chute
