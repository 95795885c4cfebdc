#include "io/xdmf_writer.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/xml_escape.hpp"

namespace granshock {

namespace {

// Shortest text that reads back as the same double, so the viewer's times match run.h5.
std::string exact(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// A DataItem naming the view dataset GROUP/name of n rows (and `components` columns
// when more than one).
std::string data_item(const std::string& h5, const std::string& group, const std::string& name,
                      long n, int components, bool integer) {
  std::ostringstream out;
  out << "<DataItem Dimensions=\"" << n;
  if (components > 1) out << " " << components;
  out << "\" NumberType=\"" << (integer ? "Int" : "Float") << "\" Precision=\"" << (integer ? 4 : 8)
      << "\" Format=\"HDF\">" << h5 << ":" << group << "/" << xml_escape(name) << "</DataItem>";
  return out.str();
}

}  // namespace

std::string obstacle_grid_xml(const std::vector<std::array<double, 2>>& outline, int dim,
                              int indent, const std::vector<FrameViewArray>& arrays) {
  const std::size_t n = outline.size();
  if (n < 3) return {};
  const std::string pad(std::size_t(indent), ' ');
  std::ostringstream out;
  out << pad << "<Grid Name=\"obstacle\" GridType=\"Uniform\">\n"
      << pad << "  <Topology TopologyType=\"Polygon\" NumberOfElements=\"1\" NodesPerElement=\""
      << n << "\">\n"
      << pad << "    <DataItem Dimensions=\"1 " << n << "\" NumberType=\"Int\" Format=\"XML\">";
  for (std::size_t k = 0; k < n; ++k) out << (k ? " " : "") << k;
  out << "</DataItem>\n"
      << pad << "  </Topology>\n"
      << pad << "  <Geometry GeometryType=\"" << (dim == 2 ? "XY" : "XYZ") << "\">\n"
      << pad << "    <DataItem Dimensions=\"" << n << " " << dim
      << "\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">";
  for (std::size_t k = 0; k < n; ++k) {
    out << (k ? " " : "") << exact(outline[k][0]) << " " << exact(outline[k][1]);
    if (dim == 3) out << " 0";
  }
  out << "</DataItem>\n" << pad << "  </Geometry>\n";
  // The particles' arrays, zero (integers -1), so that a filter applied to the particles
  // passes over the obstacle's points: a Glyph scaled by radius draws nothing there.
  for (const FrameViewArray& a : arrays) {
    out << pad << "  <Attribute Name=\"" << xml_escape(a.name) << "\" AttributeType=\""
        << (a.components == 3 ? "Vector" : "Scalar") << "\" Center=\"Node\">\n"
        << pad << "    <DataItem Dimensions=\"" << n;
    if (a.components > 1) out << " " << a.components;
    out << "\" NumberType=\"" << (a.integer ? "Int" : "Float") << "\" Precision=\""
        << (a.integer ? 4 : 8) << "\" Format=\"XML\">";
    for (std::size_t k = 0; k < n * std::size_t(a.components); ++k)
      out << (k ? " " : "") << (a.integer ? "-1" : "0");
    out << "</DataItem>\n" << pad << "  </Attribute>\n";
  }
  out << pad << "</Grid>\n";
  return out.str();
}

void write_particles_xdmf(const std::filesystem::path& xmf_path,
                          const std::string& h5_filename_relative,
                          const std::vector<SnapshotFrame>& frames, int dim,
                          const std::vector<FrameViewArray>& arrays,
                          const std::vector<std::array<double, 2>>& obstacle_outline) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("write_particles_xdmf: dim must be 2 or 3");
  for (const SnapshotFrame& frame : frames) {
    if (frame.count < 0) {
      throw std::invalid_argument("write_particles_xdmf: frame at step " +
                                  std::to_string(frame.step) + " has a negative count");
    }
  }
  for (const FrameViewArray& a : arrays) {
    if (a.components != 1 && a.components != 3)
      throw std::invalid_argument("write_particles_xdmf: '" + a.name +
                                  "' is neither a scalar "
                                  "nor a 3-vector");
  }
  const std::string h5 = xml_escape(h5_filename_relative);

  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
      << "<Xdmf Version=\"2.0\">\n"
      << "  <Domain>\n"
      << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const long n = frames[f].count;
    if (n == 0) continue;
    const std::string group = frame_view_group(long(f));
    // With an obstacle, a frame is a spatial collection of the particles and the obstacle
    // (every XDMF reader of ParaView shows both at every time; an obstacle grid beside the
    // temporal collection made the default reader show nothing).
    const std::string obstacle = obstacle_grid_xml(obstacle_outline, dim, 8, arrays);
    const std::string pad = obstacle.empty() ? "" : "  ";
    const std::string time = "<Time Value=\"" + exact(frames[f].time) + "\"/>";
    if (!obstacle.empty())
      out << "      <Grid Name=\"step " << frames[f].step
          << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
          << "        " << time << "\n";
    out << pad << "      <Grid Name=\""
        << (obstacle.empty() ? "step " + std::to_string(frames[f].step) : std::string("particles"))
        << "\" GridType=\"Uniform\">\n";
    if (obstacle.empty()) out << "        " << time << "\n";
    out << pad << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
        << "\" NodesPerElement=\"1\">\n"
        << pad << "          " << data_item(h5, group, "vertex", n, 1, true) << "\n"
        << pad << "        </Topology>\n"
        << pad << "        <Geometry GeometryType=\"" << (dim == 2 ? "XY" : "XYZ") << "\">\n"
        << pad << "          " << data_item(h5, group, "position", n, dim, false) << "\n"
        << pad << "        </Geometry>\n";
    for (const FrameViewArray& a : arrays) {
      out << pad << "        <Attribute Name=\"" << xml_escape(a.name) << "\" AttributeType=\""
          << (a.components == 3 ? "Vector" : "Scalar") << "\" Center=\"Node\">\n"
          << pad << "          " << data_item(h5, group, a.name, n, a.components, a.integer) << "\n"
          << pad << "        </Attribute>\n";
    }
    out << pad << "      </Grid>\n";
    if (!obstacle.empty()) out << obstacle << "      </Grid>\n";
  }
  out << "    </Grid>\n"
      << "  </Domain>\n"
      << "</Xdmf>\n";
  write_file_atomically(xmf_path, out.str());
}

}  // namespace granshock
