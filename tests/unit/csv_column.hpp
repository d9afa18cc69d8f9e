#pragma once
// One named column of a CSV file the run wrote (header row first), as numbers; empty if no column has that name.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace chute {

inline std::vector<double> csv_column(const std::filesystem::path& file, const std::string& name) {
    std::ifstream in(file);
    std::string line, cell;
    std::getline(in, line);
    std::stringstream header(line);
    int column = 0;
    bool found = false;
    while (std::getline(header, cell, ','))
        if (cell == name) {
            found = true;
            break;
        } else {
            ++column;
        }
    std::vector<double> values;
    if (!found) return values;
    while (std::getline(in, line)) {
        std::stringstream row(line);
        for (int k = 0; k <= column && std::getline(row, cell, ','); ++k)
            if (k == column) values.push_back(std::stod(cell));
    }
    return values;
}

}  // namespace chute
