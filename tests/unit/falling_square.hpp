#pragma once
// A square of side 1 free to fall along y in water (2500 kg/m^3, x and rotation locked), carried body-fitted: the
// grid moves with it, water at rest enters below and leaves through a convective outflow above; slip sides 4 wide.
// Laminar, nu 1e-3, to t = 1, no outputs but the time series. Tests change what they need with --set overrides.
#include <string>

namespace chute {

inline std::string falling_square_case(int cells_x, int cells_y) {
    return R"(
name: falling_square
domain:
  x: {start: -2.0, end: 2.0, cells: )" +
           std::to_string(cells_x) + R"(}
  y: {start: -3.0, end: 5.0, cells: )" +
           std::to_string(cells_y) + R"(}
fluid: {density: 1000.0, viscosity: 1.0e-3}
boundaries:
  left: {type: slip}
  right: {type: slip}
  bottom: {type: inflow, velocity: [0.0, 0.0]}
  top: {type: outflow, kind: convective}
bodies:
  square:
    shape: rectangle
    centre: [0.0, 0.0]
    size: [1.0, 1.0]
    carrier: body_fitted
    density: 2500.0
    motion: {type: free, lock_x: true, lock_rotation: true}
numerics: {convection: van_leer, cfl: 0.5}
time: {end: 1.0}
output: {fields_interval: 0.0, plots: false}
)";
}

}  // namespace chute
