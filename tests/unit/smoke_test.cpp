#include "model/element_types.hpp"

#include <gtest/gtest.h>

TEST(ElementTypes, LookupIsCaseInsensitive) {
  auto t = gapfem::element_type_from_name("c3d8");
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(gapfem::element_info(*t).n_nodes, 8);
  EXPECT_FALSE(gapfem::element_type_from_name("C3D27").has_value());
}
