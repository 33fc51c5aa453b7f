// Reads DIR/frames.xdmf with Kitware's Xdmf3 library (the base of ParaView's Xdmf3 readers) and
// checks what a viewer would get: a temporal collection of EXPECTED_FRAMES Polyvertex grids with one
// vertex cell per point, XYZ geometry, and every node attribute with one value (or 3-vector) per
// point. Built only where Debian's libxdmf-dev is installed. Usage: xdmf3_read_check XDMF FRAMES
#include <XdmfAttribute.hpp>
#include <XdmfAttributeCenter.hpp>
#include <XdmfAttributeType.hpp>
#include <XdmfDomain.hpp>
#include <XdmfGeometry.hpp>
#include <XdmfGeometryType.hpp>
#include <XdmfGridCollection.hpp>
#include <XdmfGridCollectionType.hpp>
#include <XdmfReader.hpp>
#include <XdmfTime.hpp>
#include <XdmfTopology.hpp>
#include <XdmfTopologyType.hpp>
#include <XdmfUnstructuredGrid.hpp>

#include <cstdlib>
#include <iostream>
#include <string>

namespace {
int failures = 0;
void expect(bool condition, const std::string& message) {
  if (!condition) {
    std::cerr << "FAIL: " << message << '\n';
    ++failures;
  }
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: xdmf3_read_check FRAMES.xdmf EXPECTED_FRAMES\n";
    return 2;
  }
  const auto domain = shared_dynamic_cast<XdmfDomain>(XdmfReader::New()->read(argv[1]));
  expect(domain && domain->getNumberGridCollections() == 1, "one grid collection");
  if (failures) return 1;
  const auto collection = domain->getGridCollection(0);
  expect(collection->getType() == XdmfGridCollectionType::Temporal(), "the collection is temporal");
  const unsigned frames = collection->getNumberUnstructuredGrids();
  expect(frames == std::strtoul(argv[2], nullptr, 10), "number of frames: " + std::to_string(frames));
  double previous_time = -1e300;
  for (unsigned g = 0; g < frames; ++g) {
    const auto grid = collection->getUnstructuredGrid(g);
    const std::string name = grid->getName();
    const double time = grid->getTime()->getValue();
    expect(time > previous_time, name + ": time increases");
    previous_time = time;
    const auto geometry = grid->getGeometry();
    geometry->read();
    const unsigned points = geometry->getNumberPoints();
    expect(geometry->getType() == XdmfGeometryType::XYZ() && points > 0, name + ": XYZ geometry");
    for (unsigned i = 0; i < points; ++i)
      expect(geometry->getValue<double>(3 * i + 2) == 0.0, name + ": z = 0");
    const auto topology = grid->getTopology();
    topology->read();
    expect(topology->getType() == XdmfTopologyType::Polyvertex(), name + ": Polyvertex topology");
    expect(topology->getNumberElements() == points, name + ": one vertex cell per point");
    for (unsigned i = 0; i < topology->getSize(); ++i)
      expect(topology->getValue<unsigned>(i) == i, name + ": vertex i is point i");
    expect(grid->getNumberAttributes() == 11, name + ": 11 attributes");
    for (unsigned a = 0; a < grid->getNumberAttributes(); ++a) {
      const auto attribute = grid->getAttribute(a);
      attribute->read();
      const bool vector = attribute->getType() == XdmfAttributeType::Vector();
      expect(attribute->getCenter() == XdmfAttributeCenter::Node(),
             name + "/" + attribute->getName() + ": node");
      expect(attribute->getSize() == (vector ? 3 : 1) * points,
             name + "/" + attribute->getName() + ": " + std::to_string(attribute->getSize()) + " values");
    }
  }
  std::cout << argv[1] << ": " << frames << " frames read by Xdmf3, " << failures << " failures\n";
  return failures ? 1 : 0;
}
