// The Mesh block on the host: the struct the reader fills (its OBJ data, shared between blocks that name the
// same file, and its transform steps) and the editor's operations on one. flatten() places meshes itself
// (flatten/mesh_reuse.h: a mesh's BVH is kept across edits), so a Mesh has no appendObject.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "objects/mesh.h"
#include "scene/object_basics.h"

namespace trazo {

// The corners of a mesh's triangles, each the indices of its position, normal and uv (-1: absent), kept as one
// column per attribute, and a normal or uv column only once some corner has one. The scene holds its meshes' data
// as long as it lives, through the render: a million-triangle OBJ of positions only (a raw scan) keeps 12 MB of
// corners instead of 36 MB of (position, -1, -1).
class MeshCorners {
public:
    struct Corner { int32_t position, normal, uv; };
    static constexpr int32_t kAbsent = -1;

    MeshCorners() = default;
    MeshCorners(std::initializer_list<Corner> corners) { *this = corners; }
    MeshCorners& operator=(std::initializer_list<Corner> corners) {
        clear();
        for (const Corner& c : corners) push_back(c);
        return *this;
    }

    size_t size() const { return position_.size(); }
    bool empty() const { return position_.empty(); }
    int32_t position(size_t i) const { return position_[i]; }
    int32_t normal(size_t i) const { return normal_.empty() ? kAbsent : normal_[i]; }
    int32_t uv(size_t i) const { return uv_.empty() ? kAbsent : uv_[i]; }
    Corner operator[](size_t i) const { return {position(i), normal(i), uv(i)}; }
    // Corners by value, in order (for range-for).
    class Iterator {
    public:
        Iterator(const MeshCorners& corners, size_t i) : corners_(&corners), i_(i) {}
        Corner operator*() const { return (*corners_)[i_]; }
        Iterator& operator++() {
            ++i_;
            return *this;
        }
        bool operator==(const Iterator& o) const { return i_ == o.i_; }
        bool operator!=(const Iterator& o) const { return i_ != o.i_; }

    private:
        const MeshCorners* corners_;
        size_t i_;
    };
    Iterator begin() const { return {*this, 0}; }
    Iterator end() const { return {*this, size()}; }
    // The memory its columns hold.
    size_t heapBytes() const { return (position_.capacity() + normal_.capacity() + uv_.capacity()) * sizeof(int32_t); }

    // Room for n corners' positions (an attribute column, once made, takes the same).
    void reserve(size_t n) { position_.reserve(n); }
    void push_back(const Corner& c) {
        position_.push_back(c.position);
        pushAttribute(normal_, c.normal);
        pushAttribute(uv_, c.uv);
    }
    void set(size_t i, const Corner& c) {
        position_[i] = c.position;
        setAttribute(normal_, i, c.normal);
        setAttribute(uv_, i, c.uv);
    }
    void assign(size_t n, const Corner& c) {
        position_.assign(n, c.position);
        normal_.assign(c.normal == kAbsent ? 0 : n, c.normal);
        uv_.assign(c.uv == kAbsent ? 0 : n, c.uv);
    }
    void pop_back() {
        position_.pop_back();
        if (!normal_.empty()) normal_.pop_back();
        if (!uv_.empty()) uv_.pop_back();
    }
    void clear() {
        position_.clear();
        normal_.clear();
        uv_.clear();
    }
    // Every corner's normal, or uv, absent from now on (its column's memory freed).
    void dropNormals() { std::vector<int32_t>().swap(normal_); }
    void dropUvs() { std::vector<int32_t>().swap(uv_); }

private:
    // A column is empty (every corner absent) or holds one index per corner. Called after position_ grew.
    void pushAttribute(std::vector<int32_t>& column, int32_t index) {
        if (column.empty() && index == kAbsent) return;
        if (column.empty()) {
            column.reserve(position_.capacity());
            column.assign(position_.size() - 1, kAbsent);
        }
        column.push_back(index);
    }
    void setAttribute(std::vector<int32_t>& column, size_t i, int32_t index) {
        if (column.empty() && index == kAbsent) return;
        if (column.empty()) column.assign(position_.size(), kAbsent);
        column[i] = index;
    }

    std::vector<int32_t> position_, normal_, uv_;
};

// A mesh as read from its OBJ file, before the Mesh block's transforms (flatten/flatten_mesh.h places it).
struct MeshData {
    using Corner = MeshCorners::Corner;  // -1 = absent
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;        // one per position-index corner, see `corners`
    std::vector<float> uvs;           // 2 floats per uv
    MeshCorners corners;              // 3 per triangle, fan-triangulated
    bool hasNormals = false;
    bool hasUvs = false;
};

struct Mesh {
    static constexpr bool kReadFromFile = true;  // added by addObjectFromFile, never by newObject
    int32_t material = kDefaultMaterial;
    std::string source;  // resolved path
    std::vector<TransformStep> transforms;
    std::shared_ptr<const MeshData> data;
    SourceLocation where;
};

// The box of its positions after its transforms (each corner of their box transformed: the reader's measure);
// empty when its file did not load. Linear in the vertices (scene/transform_checks.cpp).
Aabb hostBounds(const Mesh& m);
inline void translate(Mesh& m, Vec3 delta) { translateSteps(m.transforms, delta); }
inline std::optional<Mesh> newObject(KindTag<Mesh>, Vec3, float) { return std::nullopt; }
inline void scaleAboutOrigin(Mesh& m, double factor) { scaleSteps(m.transforms, factor); }

}  // namespace trazo
