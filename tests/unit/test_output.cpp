// Output files: gather/scatter, checkpoints, field snapshots with XDMF, time series, atomic writes.
// Every test runs on any number of ranks (1 and 2 are exercised); file contents are checked on rank 0.
// Comparisons are exact (EXPECT_EQ on doubles): data are only copied and stored as IEEE doubles, so any
// difference at all is a bug.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "axis.hpp"
#include "checkpoint.hpp"
#include "field.hpp"
#include "field_output.hpp"
#include "gather.hpp"
#include "grid.hpp"
#include "hdf5_file.hpp"
#include "timeseries.hpp"

namespace chute {
namespace {

namespace fs = std::filesystem;

int world_rank() {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    return rank;
}

// A fresh directory shared by all ranks (rank 0 names, creates and finally removes it).
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        std::string name;
        if (world_rank() == 0) {
            name = (fs::temp_directory_path() /
                    ("chute_test_output_" + std::to_string(::getpid()) + "_" + std::to_string(counter)))
                       .string();
            fs::remove_all(name);
            fs::create_directories(name);
        }
        ++counter;
        int length = static_cast<int>(name.size());
        MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
        name.resize(static_cast<std::size_t>(length));
        MPI_Bcast(name.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
        path_ = name;
    }
    ~TempDir() {
        MPI_Barrier(MPI_COMM_WORLD);
        if (world_rank() == 0) {
            std::error_code ec;
            fs::remove_all(path_, ec);
        }
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

bool has_tmp_file(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".tmp") return true;
    return false;
}

// Distinct values with full mantissas, so a lost bit or a misplaced element shows.
double global_value(int I, int J, int which) {
    return std::sin(1.0 + I * 0.7310585786 + J * 1.4142135623 + which) / 3.0;
}

std::vector<double> make_global(const Grid& g, int ex, int ey, int which) {
    const int gw = g.global_nx() + ex, gh = g.global_ny() + ey;
    std::vector<double> global(static_cast<std::size_t>(gw) * gh);
    for (int J = 0; J < gh; ++J)
        for (int I = 0; I < gw; ++I) global[static_cast<std::size_t>(J) * gw + I] = global_value(I, J, which);
    return global;
}

// Fills a field (and the boundary ghost slot where the patch touches right/top) from global_value.
void fill_local(const Grid& g, Field2D& f, int ex, int ey, int which) {
    const int w = g.nx() + (ex && g.touches(Side::right) ? 1 : 0);
    const int h = g.ny() + (ey && g.touches(Side::top) ? 1 : 0);
    for (int j = 0; j < h; ++j)
        for (int i = 0; i < w; ++i) f(i, j) = global_value(i + g.lx().offset, j + g.ly().offset, which);
}

// fill_local, and the halo too as far as the global array reaches (what read_checkpoint gives back).
void fill_with_halo(const Grid& g, Field2D& f, int ex, int ey, int which) {
    const int cols = g.global_nx() + ex, rows = g.global_ny() + ey;
    for (int j = -kGhost; j < g.ny() + kGhost; ++j)
        for (int i = -kGhost; i < g.nx() + kGhost; ++i) {
            const int gi = i + g.lx().offset, gj = j + g.ly().offset;
            if (gi >= 0 && gi < cols && gj >= 0 && gj < rows) f(i, j) = global_value(gi, gj, which);
        }
}

Grid make_grid(int ranks_x = 0, int ranks_y = 0, bool periodic_x = false) {
    return Grid(Axis(uniform_lines(0, 1, 12), periodic_x), Axis(uniform_lines(0, 2, 10), false), MPI_COMM_WORLD,
                ranks_x, ranks_y);
}

// ---------------------------------------------------------------------------------------------------------
// Gather / scatter

// Scatter a global array, check each patch got its part (extra column/row included where it touches the
// right/top side), gather it back and check rank 0 has the same array. Decompositions: MPI's choice, all
// ranks along x, all along y.
TEST(Gather, ScatterThenGatherRoundTrip) {
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    const int layouts[3][2] = {{0, 0}, {size, 1}, {1, size}};
    for (const auto& layout : layouts) {
        const Grid g = make_grid(layout[0], layout[1]);
        for (int ex = 0; ex <= 1; ++ex)
            for (int ey = 0; ey <= 1; ++ey) {
                SCOPED_TRACE("ranks " + std::to_string(layout[0]) + "x" + std::to_string(layout[1]) + " extra_x " +
                             std::to_string(ex) + " extra_y " + std::to_string(ey));
                const std::vector<double> global = make_global(g, ex, ey, 0);
                Field2D f(g, -99.0);
                scatter_global(g, global, f, ex, ey);
                Field2D expected(g, -99.0);
                fill_local(g, expected, ex, ey, 0);
                EXPECT_EQ(f.raw(), expected.raw());  // ghosts other than the boundary slot untouched

                const std::vector<double> back = gather_global(g, f, ex, ey);
                if (g.rank() == 0) {
                    EXPECT_EQ(back, global);
                } else {
                    EXPECT_TRUE(back.empty());
                }
            }
    }
}

// On a periodic x axis the extra face column is face 0: gather copies column 0, whatever the ghost holds.
TEST(Gather, PeriodicExtraColumnIsColumnZero) {
    const Grid g = make_grid(0, 0, true);
    Field2D f(g, 1234.0);  // ghost slot at i = nx holds junk
    fill_local(g, f, 0, 0, 1);
    const std::vector<double> global = gather_global(g, f, 1, 0);
    if (g.rank() != 0) return;
    const int gw = g.global_nx() + 1;
    ASSERT_EQ(global.size(), static_cast<std::size_t>(gw) * g.global_ny());
    for (int J = 0; J < g.global_ny(); ++J) {
        EXPECT_EQ(global[static_cast<std::size_t>(J) * gw + gw - 1], global_value(0, J, 1));
        EXPECT_EQ(global[static_cast<std::size_t>(J) * gw + 5], global_value(5, J, 1));
    }
}

// ---------------------------------------------------------------------------------------------------------
// Checkpoints

struct CheckpointFixtureFields {
    Field2D u, v, p;
    explicit CheckpointFixtureFields(const Grid& g, double value) : u(g, value), v(g, value), p(g, value) {}
    std::vector<CheckpointField> list() { return {{"u", &u, 1, 0}, {"v", &v, 0, 1}, {"p", &p, 0, 0}}; }
};

Grid make_stretched_grid(int nx, int ny) {
    return Grid(Axis(tanh_lines(0, 1, nx, 1.3), false), Axis(geometric_lines(-1, 2, ny, 1.05), false), MPI_COMM_WORLD);
}

// Write then read: header, grid lines and every field (boundary face slots and halos included) come back bit for bit.
TEST(Checkpoint, RoundTripIsBitExact) {
    TempDir dir;
    const Grid g = make_stretched_grid(12, 10);
    CheckpointFixtureFields out(g, 0.0);
    fill_local(g, out.u, 1, 0, 1);
    fill_local(g, out.v, 0, 1, 2);
    fill_local(g, out.p, 0, 0, 3);
    const CheckpointHeader header{1234, 0.1 + 0.2, 1.0 / 3.0, 2.0 / 7.0, true};
    const fs::path path = checkpoint_path(dir.path(), header.step);
    EXPECT_EQ(path.filename(), "checkpoint_001234.h5");
    write_checkpoint(g, path, header, out.list());

    CheckpointFixtureFields in(g, -7.0);
    const CheckpointHeader back = read_checkpoint(g, path, in.list());
    EXPECT_EQ(back.step, header.step);
    EXPECT_EQ(back.time, header.time);
    EXPECT_EQ(back.dt, header.dt);
    EXPECT_EQ(back.dt_previous, header.dt_previous);
    EXPECT_TRUE(back.implicit_diffusion);
    // Read back: the patch, and its halo as far as the file's array reaches (the neighbours' values there; a
    // patch's corner halo beside an outflow face is set from nothing else on a restart).
    CheckpointFixtureFields expected(g, -7.0);
    fill_with_halo(g, expected.u, 1, 0, 1);
    fill_with_halo(g, expected.v, 0, 1, 2);
    fill_with_halo(g, expected.p, 0, 0, 3);
    EXPECT_EQ(in.u.raw(), expected.u.raw());
    EXPECT_EQ(in.v.raw(), expected.v.raw());
    EXPECT_EQ(in.p.raw(), expected.p.raw());

    const auto [x, y] = read_checkpoint_lines(path);
    EXPECT_EQ(x, g.x_axis().lines());
    EXPECT_EQ(y, g.y_axis().lines());
    if (g.rank() == 0) {
        EXPECT_FALSE(has_tmp_file(dir.path()));
    }
}

TEST(Checkpoint, WrongGridSizeIsRejectedWithMessage) {
    TempDir dir;
    const fs::path path = dir.path() / "small.h5";
    {
        const Grid g = make_stretched_grid(12, 10);
        CheckpointFixtureFields f(g, 1.0);
        write_checkpoint(g, path, {}, f.list());
    }
    const Grid big = make_stretched_grid(24, 10);
    CheckpointFixtureFields f(big, 0.0);
    try {
        read_checkpoint(big, path, f.list());
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("checkpoint grid 12x10 does not match case grid 24x10"), std::string::npos) << what;
        EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    }
}

TEST(Checkpoint, MissingFileOrFieldIsRejectedWithMessage) {
    TempDir dir;
    const Grid g = make_grid();
    CheckpointFixtureFields f(g, 0.0);
    const fs::path missing = dir.path() / "nope.h5";
    try {
        read_checkpoint(g, missing, f.list());
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(missing.string()), std::string::npos) << what;
        EXPECT_NE(what.find("no such file"), std::string::npos) << what;
    }

    const fs::path path = dir.path() / "c.h5";
    write_checkpoint(g, path, {}, {{"p", &f.p}});
    try {
        read_checkpoint(g, path, f.list());
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("has no field 'u'"), std::string::npos) << e.what();
    }

    const fs::path garbage = dir.path() / "garbage.h5";
    if (g.rank() == 0) std::ofstream(garbage) << "not HDF5";
    MPI_Barrier(MPI_COMM_WORLD);
    EXPECT_THROW(read_checkpoint(g, garbage, f.list()), std::runtime_error);
}

// A write that fails half way (here: the same field twice, which HDF5 refuses) leaves the older checkpoint
// of that name intact and no temporary file behind, and throws on every rank.
TEST(Checkpoint, FailedWriteKeepsOlderFileAndLeavesNoTmp) {
    TempDir dir;
    const Grid g = make_grid();
    CheckpointFixtureFields f(g, 0.0);
    fill_local(g, f.p, 0, 0, 4);
    const fs::path path = dir.path() / "c.h5";
    write_checkpoint(g, path, {5, 0.5, 0.1, 0.1}, f.list());

    Field2D other(g, 42.0);
    EXPECT_THROW(write_checkpoint(g, path, {6, 0.6, 0.1, 0.1}, {{"p", &other}, {"p", &other}}), std::runtime_error);
    if (g.rank() == 0) {
        EXPECT_FALSE(has_tmp_file(dir.path()));
    }

    CheckpointFixtureFields in(g, 0.0);
    const CheckpointHeader h = read_checkpoint(g, path, in.list());
    EXPECT_EQ(h.step, 5);
    fill_with_halo(g, f.p, 0, 0, 4);  // the older file's values, halo included
    EXPECT_EQ(in.p.raw(), f.p.raw());
}

TEST(Checkpoint, PruneKeepsTheNewest) {
    TempDir dir;
    if (world_rank() == 0) {
        for (long step : {3, 100, 7, 1000000, 42}) std::ofstream(checkpoint_path(dir.path(), step)) << "x";
        std::ofstream(dir.path() / "checkpoint_000099.h5.tmp") << "x";
        std::ofstream(dir.path() / "fields_000001.h5") << "x";
    }
    MPI_Barrier(MPI_COMM_WORLD);
    prune_checkpoints(dir.path(), 2);
    MPI_Barrier(MPI_COMM_WORLD);
    if (world_rank() != 0) return;
    EXPECT_FALSE(fs::exists(checkpoint_path(dir.path(), 3)));
    EXPECT_FALSE(fs::exists(checkpoint_path(dir.path(), 7)));
    EXPECT_FALSE(fs::exists(checkpoint_path(dir.path(), 42)));
    EXPECT_TRUE(fs::exists(checkpoint_path(dir.path(), 100)));
    EXPECT_TRUE(fs::exists(checkpoint_path(dir.path(), 1000000)));
    EXPECT_TRUE(fs::exists(dir.path() / "checkpoint_000099.h5.tmp"));
    EXPECT_TRUE(fs::exists(dir.path() / "fields_000001.h5"));
    EXPECT_EQ(latest_checkpoint(dir.path()), checkpoint_path(dir.path(), 1000000));
}

// ---------------------------------------------------------------------------------------------------------
// Atomic writes and the HDF5 wrapper

TEST(Output, AtomicWriteFailureKeepsOldFileAndRemovesTmp) {
    if (world_rank() != 0) return;
    const fs::path dir = fs::temp_directory_path() / ("chute_test_atomic_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path target = dir / "file.txt";
    write_atomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "old good"; });
    EXPECT_EQ(read_text(target), "old good");
    EXPECT_THROW(write_atomically(target,
                                  [](const fs::path& tmp) {
                                      std::ofstream(tmp) << "half writ";
                                      throw std::runtime_error("disk full");
                                  }),
                 std::runtime_error);
    EXPECT_EQ(read_text(target), "old good");
    EXPECT_FALSE(has_tmp_file(dir));
    write_atomically(target, [](const fs::path& tmp) { std::ofstream(tmp) << "new"; });
    EXPECT_EQ(read_text(target), "new");
    fs::remove_all(dir);
}

TEST(Output, Hdf5FileRoundTripAndErrorsNameFileAndDataset) {
    if (world_rank() != 0) return;
    const fs::path path = fs::temp_directory_path() / ("chute_test_h5_" + std::to_string(::getpid()) + ".h5");
    {
        Hdf5File f = Hdf5File::create(path);
        f.write("a/b/line", std::vector<double>{1.5, 2.5, 3.5});
        f.write("grid2d", std::vector<double>{1, 2, 3, 4, 5, 6}, 2, 3);
        f.write_double("scalar", 0.1);
        f.write_int("count", -12345678901LL);
        f.write("empty", std::vector<double>{});
        f.set_string_attribute("/", "name", "chute run");
        f.set_double_attribute("grid2d", "scale", 2.0);
        f.set_int_attribute("/", "step", 7);
        f.close();
    }
    Hdf5File f = Hdf5File::open_read(path);
    EXPECT_TRUE(f.has("a/b/line"));
    EXPECT_TRUE(f.has("/a/b"));
    EXPECT_FALSE(f.has("a/c/line"));
    EXPECT_EQ(f.members("/"), (std::vector<std::string>{"a", "count", "empty", "grid2d", "scalar"}));
    EXPECT_EQ(f.read("a/b/line"), (std::vector<double>{1.5, 2.5, 3.5}));
    EXPECT_EQ(f.shape("grid2d"), (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(f.read_block("grid2d", 1, 1, 1, 2), (std::vector<double>{5, 6}));
    EXPECT_EQ(f.read_double("scalar"), 0.1);
    EXPECT_EQ(f.read_int("count"), -12345678901LL);
    EXPECT_TRUE(f.read("empty").empty());
    EXPECT_EQ(f.string_attribute("/", "name"), "chute run");
    EXPECT_EQ(f.double_attribute("grid2d", "scale"), 2.0);
    EXPECT_EQ(f.int_attribute("/", "step"), 7);
    try {
        f.read("missing");
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(path.string()), std::string::npos) << what;
        EXPECT_NE(what.find("'missing'"), std::string::npos) << what;
    }
    EXPECT_THROW(f.read_block("grid2d", 1, 1, 2, 2), std::runtime_error);
    f.close();
    fs::remove(path);
}

// Two snapshots (with moved grid lines in between): each .h5 holds its lines and the gathered fields; the
// XDMF lists both files' dataset paths and times.
TEST(Output, FieldOutputWritesSnapshotsAndXdmf) {
    TempDir dir;
    Grid g = make_grid();
    Field2D p(g), w(g);
    fill_local(g, p, 0, 0, 5);
    fill_local(g, w, 0, 0, 6);
    FieldOutput output(g, dir.path());
    output.write(0, 0.0, {{"p", &p}, {"vorticity", &w}});
    std::vector<double> x2 = g.x_axis().lines();
    x2[5] += 0.01;
    g.set_lines(x2, g.y_axis().lines());
    output.write(10, 0.25, {{"p", &p}, {"vorticity", &w}});
    MPI_Barrier(MPI_COMM_WORLD);
    if (g.rank() != 0) return;

    EXPECT_FALSE(has_tmp_file(dir.path()));
    Hdf5File f = Hdf5File::open_read(dir.path() / "fields_000010.h5");
    EXPECT_EQ(f.read("x"), x2);
    EXPECT_EQ(f.read("y"), g.y_axis().lines());
    EXPECT_EQ(f.shape("p"), (std::vector<std::size_t>{10, 12}));
    EXPECT_EQ(f.read("vorticity"), make_global(g, 0, 0, 6));
    EXPECT_EQ(f.double_attribute("/", "time"), 0.25);
    EXPECT_EQ(f.int_attribute("/", "step"), 10);
    Hdf5File f0 = Hdf5File::open_read(dir.path() / "fields_000000.h5");
    EXPECT_EQ(f0.read("x"), uniform_lines(0, 1, 12));

    const std::string xdmf = read_text(dir.path() / "fields.xdmf");
    for (const char* needle :
         {"fields_000000.h5:/p", "fields_000000.h5:/vorticity", "fields_000010.h5:/p", "fields_000010.h5:/x",
          "fields_000010.h5:/y", "<Time Value=\"0\"/>", "<Time Value=\"0.25\"/>", "CollectionType=\"Temporal\"",
          "TopologyType=\"2DRectMesh\" Dimensions=\"11 13\"", "GeometryType=\"VXVY\"", "Center=\"Cell\"",
          "Dimensions=\"10 12\""})
        EXPECT_NE(xdmf.find(needle), std::string::npos) << needle;
}

// After a restart from step 10, the index lists the earlier snapshots up to step 10 and the new ones, but
// not those of the stopped run after step 10.
TEST(Output, FieldOutputRestartIndexesEarlierSnapshots) {
    TempDir dir;
    const Grid g = make_grid();
    Field2D p(g, 1.0);
    {
        FieldOutput output(g, dir.path());
        for (long step : {0, 10, 20}) output.write(step, 0.125 * step, {{"p", &p}});
    }
    FieldOutput output(g, dir.path(), 10);
    output.write(15, 1.875, {{"p", &p}});
    MPI_Barrier(MPI_COMM_WORLD);
    if (g.rank() != 0) return;
    const std::string xdmf = read_text(dir.path() / "fields.xdmf");
    EXPECT_NE(xdmf.find("fields_000000.h5:/p"), std::string::npos);
    EXPECT_NE(xdmf.find("<Time Value=\"1.25\"/>"), std::string::npos);
    EXPECT_NE(xdmf.find("fields_000010.h5:/p"), std::string::npos);
    EXPECT_NE(xdmf.find("fields_000015.h5:/p"), std::string::npos);
    EXPECT_EQ(xdmf.find("fields_000020.h5"), std::string::npos);
    EXPECT_LT(xdmf.find("fields_000010.h5"), xdmf.find("fields_000015.h5"));
}

// ---------------------------------------------------------------------------------------------------------
// Time series

TEST(TimeSeries, RestartKeepsRowsUpToRestartTime) {
    TempDir dir;
    const Grid g = make_grid();
    const std::vector<std::string> columns = {"t", "cfl", "F/x"};
    {
        TimeSeries ts(g, dir.path(), columns);
        for (int k = 0; k <= 5; ++k) ts.append({0.25 * k, 0.1 * k, 1.0 / (k + 3)});
    }
    {
        TimeSeries ts(g, dir.path(), columns, 0.5);  // keeps t = 0, 0.25, 0.5
        if (g.rank() == 0) {
            EXPECT_EQ(ts.rows(), 3u);
        }
        ts.append({0.625, 9.0, 8.0});
        ts.write_hdf5();
    }
    MPI_Barrier(MPI_COMM_WORLD);
    if (g.rank() != 0) return;
    const std::string expected_text = "t,cfl,F/x\n0,0,0.3333333333333333\n0.25,0.1,0.25\n0.5,0.2,0.2\n0.625,9,8\n";
    EXPECT_EQ(read_text(dir.path() / "timeseries.csv"), expected_text);
    Hdf5File f = Hdf5File::open_read(dir.path() / "timeseries.h5");
    EXPECT_EQ(f.read("t"), (std::vector<double>{0, 0.25, 0.5, 0.625}));
    EXPECT_EQ(f.read("F_x"), (std::vector<double>{1.0 / 3, 0.25, 0.2, 8}));
    EXPECT_EQ(f.string_attribute("/", "columns"), "t,cfl,F/x");
    EXPECT_FALSE(has_tmp_file(dir.path()));
}

// A last line cut short by a crash is dropped; a new series (restart_time < 0) starts from the header.
TEST(TimeSeries, RestartDropsTruncatedLastLineAndNewSeriesStartsEmpty) {
    TempDir dir;
    const Grid g = make_grid();
    if (g.rank() == 0) std::ofstream(dir.path() / "timeseries.csv") << "t,a\n0,1\n1,2\n2,3.1";
    MPI_Barrier(MPI_COMM_WORLD);
    {
        TimeSeries ts(g, dir.path(), {"t", "a"}, 10.0);
        if (g.rank() == 0) {
            EXPECT_EQ(ts.rows(), 2u);
        }
        EXPECT_THROW(ts.append({1.0}), std::invalid_argument);
    }
    if (g.rank() == 0) {
        EXPECT_EQ(read_text(dir.path() / "timeseries.csv"), "t,a\n0,1\n1,2\n");
    }
    {
        TimeSeries ts(g, dir.path(), {"t", "a"});
        ts.write_hdf5();
    }
    if (g.rank() != 0) return;
    EXPECT_EQ(read_text(dir.path() / "timeseries.csv"), "t,a\n");
    EXPECT_TRUE(Hdf5File::open_read(dir.path() / "timeseries.h5").read("t").empty());
    EXPECT_THROW(TimeSeries(g, dir.path(), {"t", "b"}, 0.0), std::runtime_error);  // columns differ
}

}  // namespace
}  // namespace chute
