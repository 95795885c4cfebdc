// The mean-velocity vectors of fields.h5 and fields.xmf (io/fields_file.hpp, cell_vectors):
// views of the ux and uy fields that viewers take as one vector per cell.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io/fields_file.hpp"
#include "io/fields_xdmf.hpp"
#include "io/io_test_support.hpp"

namespace granshock {
namespace {

FieldsFileContent two_by_three() {
  FieldsFileContent c;
  c.nx = 3;
  c.ny = 2;
  c.dx = c.dy = 1e-3;
  auto field = [&](const char* name, double base) {
    FieldsFileContent::CellField f;
    f.name = name;
    for (int k = 0; k < 6; ++k) f.values.push_back(base + k);
    c.cell_fields.push_back(f);
  };
  field("T", 100);
  field("ux", 10);
  field("uy", 20);
  field("ux_steel", 30);
  field("uy_steel", 40);
  field("ux_lonely", 50);  // no uy_lonely: no vector
  field("uxx", 60);        // not a velocity component
  return c;
}

TEST(FieldsVectors, MeanVelocitiesWhereBothComponentsExist) {
  const std::vector<CellVector> v = cell_vectors(two_by_three());
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].name, "u");
  EXPECT_EQ(v[0].x, "ux");
  EXPECT_EQ(v[0].y, "uy");
  EXPECT_EQ(v[1].name, "u_steel");
  EXPECT_EQ(v[1].y, "uy_steel");
}

TEST(FieldsVectors, AreViewsOfTheComponentsWithZeroZ) {
  test::TempDir dir;
  const FieldsFileContent c = two_by_three();
  write_fields_file(dir / "fields.h5", c);
  write_fields_xdmf(dir / "fields.xmf", "fields.h5", c);
  const auto u = test::read_array<double>(dir / "fields.h5", "/vectors/u_steel");
  EXPECT_EQ(u.shape, (std::vector<hsize_t>{2, 3, 3}));
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(u.values[std::size_t(3 * k)], 30.0 + k);
    EXPECT_EQ(u.values[std::size_t(3 * k + 1)], 40.0 + k);
    EXPECT_EQ(u.values[std::size_t(3 * k + 2)], 0.0);
  }
  EXPECT_FALSE(test::has_object(dir / "fields.h5", "/vectors/u_lonely"));
  std::ifstream in(dir / "fields.xmf");
  std::stringstream xml;
  xml << in.rdbuf();
  EXPECT_NE(xml.str().find("<Attribute Name=\"u\" AttributeType=\"Vector\" Center=\"Cell\">\n"
                           "        <DataItem Dimensions=\"2 3 3\" NumberType=\"Float\" "
                           "Precision=\"8\" Format=\"HDF\">fields.h5:/vectors/u</DataItem>"),
            std::string::npos)
      << xml.str();
}

}  // namespace
}  // namespace granshock
