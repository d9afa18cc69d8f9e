#include "timeseries.hpp"

#include <charconv>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "append_file.hpp"
#include "exact_text.hpp"
#include "hdf5_file.hpp"

namespace chute {

namespace {

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (std::size_t k = 0; k < items.size(); ++k) {
        if (k > 0) out += ',';
        out += items[k];
    }
    return out;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> items;
    std::string item;
    std::istringstream in(line);
    while (std::getline(in, item, ',')) items.push_back(item);
    if (!line.empty() && line.back() == ',') items.emplace_back();
    return items;
}

std::string strip_cr(std::string s) {
    if (!s.empty() && s.back() == '\r') s.pop_back();
    return s;
}

// Parses a CSV row of numbers; false if any item is not a number.
bool parse_row(const std::string& line, std::size_t columns, std::vector<double>& row) {
    const std::vector<std::string> items = split(line);
    if (items.size() != columns) return false;
    row.resize(columns);
    for (std::size_t k = 0; k < columns; ++k) {
        const char* begin = items[k].c_str();
        char* end = nullptr;
        row[k] = std::strtod(begin, &end);
        if (end == begin || *end != '\0') return false;
    }
    return true;
}

}  // namespace

TimeSeries::TimeSeries(const Grid& grid, std::filesystem::path out_dir, std::vector<std::string> columns,
                       double restart_time, std::string stem)
    : root_(grid.rank() == 0), out_dir_(std::move(out_dir)), stem_(std::move(stem)), columns_(std::move(columns)) {
    if (columns_.empty()) throw std::invalid_argument("TimeSeries: no columns");
    if (!root_) return;
    std::filesystem::create_directories(out_dir_);
    const std::filesystem::path csv = csv_path();
    const std::string header = join(columns_);

    std::vector<std::string> kept_lines;
    if (restart_time >= 0.0 && std::filesystem::exists(csv)) {
        std::ifstream in(csv, std::ios::binary);
        if (!in) throw std::runtime_error("cannot read time series '" + csv.string() + "'");
        std::stringstream buffer;
        buffer << in.rdbuf();
        const std::string text = buffer.str();
        std::vector<std::string> lines;
        std::istringstream stream(text);
        for (std::string line; std::getline(stream, line);) lines.push_back(strip_cr(line));
        // A last line without its newline was cut short by a crash: drop it.
        if (!text.empty() && text.back() != '\n' && !lines.empty()) lines.pop_back();
        if (!lines.empty() && lines.front() != header)
            throw std::runtime_error("time series '" + csv.string() + "' has columns '" + lines.front() +
                                     "', this run writes '" + header +
                                     "': move the old file away to start a new series");
        std::vector<double> row;
        for (std::size_t k = 1; k < lines.size(); ++k) {
            if (!parse_row(lines[k], columns_.size(), row)) continue;  // blank or damaged line
            if (row[0] <= restart_time) {
                kept_lines.push_back(lines[k]);
                rows_.push_back(row);
            }
        }
    }

    std::string text = header + '\n';
    for (const std::string& line : kept_lines) text += line + '\n';
    write_text_atomically(csv, text);
    csv_ = AppendFile(csv);
}

void TimeSeries::append(const std::vector<double>& row) {
    if (row.size() != columns_.size())
        throw std::invalid_argument("TimeSeries::append: " + std::to_string(row.size()) + " values for " +
                                    std::to_string(columns_.size()) + " columns");
    if (!root_) return;
    std::string line;
    for (std::size_t k = 0; k < row.size(); ++k) {
        if (k > 0) line += ',';
        line += exact_text(row[k]);
    }
    line += '\n';
    csv_.append(line);
    rows_.push_back(row);
}

void TimeSeries::write_hdf5() {
    if (!root_) return;
    write_atomically(hdf5_path(), [&](const std::filesystem::path& tmp) {
        Hdf5File file = Hdf5File::create(tmp);
        file.set_string_attribute("/", "columns", join(columns_));
        std::vector<double> column(rows_.size());
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            std::string name = columns_[c];
            for (char& ch : name)
                if (ch == '/') ch = '_';
            if (name.empty() || name == ".") name = "column_" + std::to_string(c);
            for (std::size_t r = 0; r < rows_.size(); ++r) column[r] = rows_[r][c];
            file.write(name, column);
        }
        file.close();
    });
}

}  // namespace chute
