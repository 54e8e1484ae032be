// Links an installed globe: the planet's polyhedron on the CPU and a Vulkan device.
#include <globe/engine/vk/device.h>
#include <globe/planet/geometry/triacontahedron.h>

#include <cstdio>

int main() {
  const globe::Triacontahedron& polyhedron = globe::Triacontahedron::get();
  globe::vk::Device device(globe::vk::DeviceOptions{});
  std::printf("consumer: edge arc %.4f rad, device %s\n", polyhedron.edgeArc(), device.name().c_str());
  return polyhedron.edgeArc() > 0.65 && polyhedron.edgeArc() < 0.66 ? 0 : 1;
}
