// The grid lines an axis of the case describes (flow_config.hpp): its `spacing` choice and parameters, made by
// the generators of grid/axis.hpp.
#include "axis.hpp"
#include "flow_config.hpp"

namespace chute {

std::vector<double> axis_lines(const AxisConfig& c) {
    if (c.spacing == "lines") return c.lines;
    if (c.spacing == "tanh") return tanh_lines(c.start, c.end, c.cells, c.beta);
    if (c.spacing == "clustered")
        return clustered_lines(c.start, c.end, c.core[0], c.core[1], c.core_cells, c.ratio, c.first, c.max_width);
    if (c.spacing == "geometric") return geometric_lines(c.start, c.end, c.cells, c.ratio);
    return uniform_lines(c.start, c.end, c.cells);
}

}  // namespace chute
