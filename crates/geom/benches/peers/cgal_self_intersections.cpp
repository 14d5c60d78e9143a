// The peer of `benches/crossings.rs`: CGAL's self-intersection test
// (Polygon_mesh_processing::self_intersections, sequential, exact predicates) on an OBJ's
// faces fanned from their first corner into triangles, as Prism's search and renderer draw
// them. Prints the triangles, the intersecting pairs (CGAL counts triangles that touch, too,
// and a degenerate triangle as a pair with itself) and the time of the test alone, the mesh
// built in memory first. With `OUT` it writes each pair's six vertex indices.
//
//   apt-get install libcgal-dev   # CGAL 5.5 on Debian 12
//   g++ -O3 -DNDEBUG -std=c++17 cgal_self_intersections.cpp -o cgal_self_intersections -lgmp -lmpfr
//   prism subdivide assets/computer-room.obj -o /tmp/level5.obj --clamp \
//       --pipeline combination:r=0.2,combination:r=0.2,combination:r=0.2,combination:r=0.2,combination:r=0.2
//   ./cgal_self_intersections /tmp/level5.obj [OUT]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <chrono>
#include <fstream>
#include <sstream>
#include <iostream>
#include <vector>
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PMP = CGAL::Polygon_mesh_processing;
int main(int argc, char** argv) {
  std::ifstream in(argv[1]);
  Mesh m;
  std::vector<Mesh::Vertex_index> vs;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tag; s >> tag;
    if (tag == "v") { double x, y, z; s >> x >> y >> z; vs.push_back(m.add_vertex(K::Point_3(x, y, z))); }
    else if (tag == "f") {
      std::vector<Mesh::Vertex_index> f; std::string w;
      while (s >> w) f.push_back(vs[std::stoi(w.substr(0, w.find('/'))) - 1]);
      for (size_t i = 1; i + 1 < f.size(); ++i) {
        if (m.add_face(f[0], f[i], f[i + 1]) == Mesh::null_face()) { std::cerr << "non-manifold face\n"; return 1; }
      }
    }
  }
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> out;
  auto t0 = std::chrono::steady_clock::now();
  PMP::self_intersections(m, std::back_inserter(out));
  auto t1 = std::chrono::steady_clock::now();
  if (argc > 2) {
    std::ofstream o(argv[2]);
    for (auto& p : out) {
      for (auto f : {p.first, p.second}) {
        for (auto v : m.vertices_around_face(m.halfedge(f))) o << int(v) << " ";
      }
      o << "\n";
    }
  }
  size_t degenerate = 0;
  for (auto& p : out) degenerate += p.first == p.second;
  std::cout << "triangles=" << m.number_of_faces() << " pairs=" << out.size() << " degenerate=" << degenerate
            << " time_ms=" << std::chrono::duration<double, std::milli>(t1 - t0).count() << "\n";
}
