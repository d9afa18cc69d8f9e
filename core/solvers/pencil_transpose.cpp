#include "pencil_transpose.hpp"

#include <algorithm>
#include <stdexcept>

namespace chute {

namespace {

CellBox intersection(const CellBox& a, const CellBox& b) {
    return {std::max(a.i0, b.i0), std::min(a.i1, b.i1), std::max(a.j0, b.j0), std::min(a.j1, b.j1)};
}

std::vector<CellBox> all_boxes(MPI_Comm comm, const CellBox& mine) {
    int size = 1;
    MPI_Comm_size(comm, &size);
    std::vector<CellBox> boxes(size);
    const int local[4] = {mine.i0, mine.i1, mine.j0, mine.j1};
    std::vector<int> all(4 * size);
    MPI_Allgather(local, 4, MPI_INT, all.data(), 4, MPI_INT, comm);
    for (int r = 0; r < size; ++r) boxes[r] = {all[4 * r], all[4 * r + 1], all[4 * r + 2], all[4 * r + 3]};
    return boxes;
}

std::ptrdiff_t at(const BoxStorage& s, int i, int j) { return (i - s.box.i0) * s.si + (j - s.box.j0) * s.sj; }

// Copy the cells of `box` from one storage to another; runs along x are copied whole where both store x fastest.
void copy_cells(const CellBox& box, const double* from, const BoxStorage& fs, double* to, const BoxStorage& ts) {
    const int width = box.i1 - box.i0;
    if (width <= 0) return;
    for (int j = box.j0; j < box.j1; ++j) {
        const double* in = from + at(fs, box.i0, j);
        double* out = to + at(ts, box.i0, j);
        if (fs.si == 1 && ts.si == 1) {
            std::copy(in, in + width, out);
        } else {
            for (int k = 0; k < width; ++k) out[k * ts.si] = in[k * fs.si];
        }
    }
}

}  // namespace

PencilTranspose::PencilTranspose(MPI_Comm comm, const BoxStorage& from, const BoxStorage& to)
    : comm_(comm), from_(from), to_(to) {
    int rank = 0, size = 1;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
    const std::vector<CellBox> sources = all_boxes(comm, from.box), targets = all_boxes(comm, to.box);
    send_counts_.assign(size, 0);
    send_offsets_.assign(size, 0);
    receive_counts_.assign(size, 0);
    receive_offsets_.assign(size, 0);
    int sent = 0, received = 0;
    long long covered = 0;
    for (int r = 0; r < size; ++r) {
        const CellBox out = intersection(from.box, targets[r]), in = intersection(sources[r], to.box);
        covered += in.cells();
        if (r == rank) {
            self_ = out;
            continue;
        }
        send_offsets_[r] = sent;
        receive_offsets_[r] = received;
        send_counts_[r] = static_cast<int>(out.cells());
        receive_counts_[r] = static_cast<int>(in.cells());
        if (out.cells() > 0) sends_.push_back({out, r, sent});
        if (in.cells() > 0) receives_.push_back({in, r, received});
        sent += send_counts_[r];
        received += receive_counts_[r];
    }
    if (covered != to.box.cells())
        throw std::logic_error("PencilTranspose: the source boxes do not cover this rank's target box");
    send_buffer_.resize(sent);
    receive_buffer_.resize(received);
    int crossing = sent + received > 0 ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &crossing, 1, MPI_INT, MPI_MAX, comm);
    alone_ = crossing == 0;
}

void PencilTranspose::run(const double* from, double* to) {
    copy_cells(self_, from, from_, to, to_);
    if (alone_) return;
    for (const Block& b : sends_)  // the buffer holds each block x fastest
        copy_cells(b.box, from, from_, send_buffer_.data() + b.offset, BoxStorage{b.box, 1, b.box.i1 - b.box.i0});
    MPI_Alltoallv(send_buffer_.data(), send_counts_.data(), send_offsets_.data(), MPI_DOUBLE, receive_buffer_.data(),
                  receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE, comm_);
    for (const Block& b : receives_)
        copy_cells(b.box, receive_buffer_.data() + b.offset, BoxStorage{b.box, 1, b.box.i1 - b.box.i0}, to, to_);
}

}  // namespace chute
