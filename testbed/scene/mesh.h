#pragma once
// The mesh type every part of the testbed shares: OpenMesh triangles with normals, so the
// same object feeds the GPU upload, the silhouette extraction of the ground truth and the
// ray caster.
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace testbed {

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3f;
  using Normal = OpenMesh::Vec3f;
  VertexAttributes(OpenMesh::Attributes::Normal);
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

}  // namespace testbed
