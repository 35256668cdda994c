#pragma once
// What a glTF 2.0 reader must refuse before it reads any geometry, said as what it is rather
// than as whatever breaks first: a file of another version (glTF 1.0's JSON parses, but its
// dictionaries and techniques mean something else, so it "has no triangles"), and a required
// extension that stores the geometry in a way we do not read (the specification, 3.12: a file
// whose extensionsRequired a loader does not support MUST NOT be loaded).

#include <cstddef>
#include <string>

#include <tiny_gltf.h>

namespace wt {

// A .glb's header and chunks, before tinygltf reads them: version 1 is glTF 1.0's binary
// container (KHR_binary_glTF); a BIN chunk whose length runs past the file's is refused, since
// tinygltf 2.7 bounds the chunk without its 8-byte header and would read up to 8 bytes past the
// end of the mapped file (past its last page: a crash). What tinygltf refuses itself it refuses.
void check_glb_container(const std::string& path, const unsigned char* data, std::size_t size);

// After tinygltf has parsed the file: asset.version and extensionsRequired.
void check_gltf_version_and_extensions(const std::string& path, const tinygltf::Model& model);

// After tinygltf has refused the file: if its JSON (the whole file, or a .glb's JSON chunk)
// says glTF 1.0 (asset.version 1 or "1.x", or no version and 1.0's dictionaries where 2.0 has
// arrays) or requires an extension we do not read, throws MeshFileError saying so; otherwise
// returns, for tinygltf's own message.
void explain_gltf_refusal(const std::string& path, const unsigned char* data, std::size_t size, bool binary);

}  // namespace wt
