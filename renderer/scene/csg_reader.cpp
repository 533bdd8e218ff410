// CSG reader (host): blocks → nodes through the CSG tables, child references → indices, then tree checks.
#include "scene/csg_reader.h"

#include <algorithm>
#include <optional>
#include <vector>

#include "scene/block_lexer.h"
#include "scene/block_table.h"
#include "scene/source_file.h"

namespace trazo {
namespace {

using Kind = CsgNode::Kind;

struct KindName {
    std::string_view name;
    Kind kind;
};
constexpr KindName kKinds[] = {{"Sphere", Kind::Sphere},       {"Box", Kind::Box},
                               {"Cylinder", Kind::Cylinder},   {"Union", Kind::Union},
                               {"Difference", Kind::Difference}, {"Intersection", Kind::Intersection}};
constexpr int kKindCount = 6;

bool isOperation(Kind k) { return k == Kind::Union || k == Kind::Difference || k == Kind::Intersection; }

int kindIndex(std::string_view name) {
    for (int k = 0; k < kKindCount; ++k)
        if (kKinds[k].name == name) return k;
    return -1;
}

std::span<const ParamSpec<CsgNodeDraft>> tableFor(Kind k) {
    switch (k) {
        case Kind::Sphere: return csgSphereTable();
        case Kind::Box: return csgBoxTable();
        case Kind::Cylinder: return csgCylinderTable();
        default: return csgOperationTable();
    }
}

size_t errorCount(const Diagnostics& diags) {
    return size_t(std::count_if(diags.items.begin(), diags.items.end(),
                                [](const Diagnostic& d) { return d.severity == Severity::Error; }));
}

class CsgBuilder {
public:
    CsgBuilder(const std::string& file, Diagnostics& diags) : file_(file), diags_(diags) {}

    void addBlock(const Block& block) {
        if (block.identifier.empty()) return;  // a nameless '{', already reported
        const int k = kindIndex(block.identifier);
        if (k < 0) {
            std::vector<std::string_view> names = blockNames(csgBlocks());
            diags_.error(block.where, "unknown block '" + block.identifier + "' in a CSG file",
                         didYouMean(block.identifier, names));
            return;
        }
        // §4: primitives carry no Material; the scene's CSG block gives one material to the whole solid.
        Block filtered = block;
        std::erase_if(filtered.parameters, [&](const ParameterLine& line) {
            if (line.name != "Material") return false;
            diags_.warning({file_, line.line, 0},
                           "Material is ignored in a CSG file (the scene's CSG block gives the material)");
            return true;
        });
        CsgNodeDraft draft;
        draft.node.kind = kKinds[k].kind;
        draft.node.where = block.where;
        readParameters(filtered, tableFor(draft.node.kind), draft, diags_);
        ordinal_.push_back(int(byKind_[k].size()));
        byKind_[k].push_back(int(drafts_.size()));
        if (isOperation(draft.node.kind)) operations_.push_back(int(drafts_.size()));
        drafts_.push_back(std::move(draft));
    }

    std::shared_ptr<const CsgTree> build(size_t errorsBefore) {
        if (drafts_.empty()) {
            if (errorCount(diags_) == errorsBefore) diags_.error({file_, 0, 0}, "CSG file has no nodes");
            return nullptr;
        }
        if (drafts_.size() > size_t(kMaxCsgNodes)) {
            diags_.error(drafts_[size_t(kMaxCsgNodes)].node.where,
                         "too many CSG nodes: the file has " + std::to_string(drafts_.size()) + ", at most " +
                             std::to_string(kMaxCsgNodes) + " are supported");
            return nullptr;
        }
        for (CsgNodeDraft& d : drafts_) {
            if (!isOperation(d.node.kind)) continue;
            d.node.left = resolveChild(d.leftType, d.leftIndex, d.leftIndexAt, "LeftIndex");
            d.node.right = resolveChild(d.rightType, d.rightIndex, d.rightIndexAt, "RightIndex");
        }
        if (errorCount(diags_) != errorsBefore) return nullptr;
        if (!linkParents() || !checkSingleRoot()) return nullptr;
        auto tree = std::make_shared<CsgTree>();
        for (CsgNodeDraft& d : drafts_) tree->nodes.push_back(std::move(d.node));
        tree->root = root_;
        return tree;
    }

private:
    std::string describe(int node) const {
        return std::string(kindName(node)) + " " + std::to_string(ordinal_[size_t(node)]);
    }
    std::string_view kindName(int node) const {
        for (const KindName& k : kKinds)
            if (k.kind == drafts_[size_t(node)].node.kind) return k.name;
        return {};
    }
    std::string lineOf(int node) const { return std::to_string(drafts_[size_t(node)].node.where.line); }

    int resolveChild(const NameRef& type, int index, const SourceLocation& indexAt, const char* indexName) {
        if (type.name.empty() || index < 0) return -1;  // missing or negative: already reported
        const std::vector<int>* list = &operations_;
        std::string what = "operation block";
        if (type.name != "Operation") {
            const int k = kindIndex(type.name);
            if (k < 0) {
                std::vector<std::string_view> names = {"Sphere", "Box", "Cylinder", "Operation",
                                                       "Union", "Difference", "Intersection"};
                diags_.error(type.at, "unknown node type '" + type.name + "'", didYouMean(type.name, names));
                return -1;
            }
            list = &byKind_[k];
            what = type.name + " block";
        }
        if (size_t(index) >= list->size()) {
            diags_.error(indexAt, std::string(indexName) + " " + std::to_string(index) +
                                      " is out of range (the file has " + std::to_string(list->size()) + " " +
                                      what + (list->size() == 1 ? ")" : "s)"));
            return -1;
        }
        return (*list)[size_t(index)];
    }

    // Every node gets at most one parent; a second reference would make a DAG, which §4's tree is not.
    bool linkParents() {
        parent_.assign(drafts_.size(), -1);
        bool ok = true;
        for (int op : operations_) {
            const CsgNodeDraft& d = drafts_[size_t(op)];
            const std::pair<int, const SourceLocation*> children[] = {{d.node.left, &d.leftIndexAt},
                                                                     {d.node.right, &d.rightIndexAt}};
            for (const auto& [child, at] : children) {
                if (child == op) {
                    diags_.error(*at, "cycle: " + describe(op) + " uses itself");
                    ok = false;
                } else if (parent_[size_t(child)] >= 0) {
                    diags_.error(*at, describe(child) + " is already used by the operation at line " +
                                          lineOf(parent_[size_t(child)]) +
                                          " (a CSG file describes a tree; nodes cannot be shared)");
                    ok = false;
                } else {
                    parent_[size_t(child)] = op;
                }
            }
        }
        return ok;
    }

    bool checkSingleRoot() {
        std::vector<int> roots;
        for (size_t i = 0; i < drafts_.size(); ++i)
            if (parent_[i] < 0) roots.push_back(int(i));
        if (roots.size() > 1) {
            std::string lines;
            for (size_t k = 0; k < roots.size(); ++k) {
                lines += (k == 0 ? "" : (k + 1 == roots.size() ? " and " : ", ")) + lineOf(roots[k]);
            }
            diags_.error(drafts_[size_t(roots[1])].node.where,
                         "several roots: the nodes at lines " + lines + " are used by no operation");
            return false;
        }
        std::vector<bool> reached(drafts_.size(), false);
        if (roots.size() == 1) {
            std::vector<int> stack = {roots[0]};
            while (!stack.empty()) {
                const int n = stack.back();
                stack.pop_back();
                reached[size_t(n)] = true;
                for (int c : {drafts_[size_t(n)].node.left, drafts_[size_t(n)].node.right})
                    if (c >= 0 && !reached[size_t(c)]) stack.push_back(c);
            }
        }
        for (size_t i = 0; i < drafts_.size(); ++i) {
            if (reached[i]) continue;
            // Every unreached node has a parent, so following parents must loop: report one node of the loop.
            std::vector<bool> seen(drafts_.size(), false);
            int n = int(i);
            while (!seen[size_t(n)]) {
                seen[size_t(n)] = true;
                n = parent_[size_t(n)];
            }
            const std::string where = roots.empty() ? "no root (every node is used by an operation); " : "";
            diags_.error(drafts_[size_t(n)].node.where, where + "cycle: " + describe(n) + " contains itself");
            return false;
        }
        root_ = roots[0];
        return true;
    }

    const std::string& file_;
    Diagnostics& diags_;
    std::vector<CsgNodeDraft> drafts_;
    std::vector<int> ordinal_;  // index of each node among the blocks of its own kind
    std::vector<int> byKind_[kKindCount];
    std::vector<int> operations_;
    std::vector<int> parent_;
    int root_ = -1;
};

}  // namespace

std::shared_ptr<const CsgTree> readCsgText(const std::string& text, const std::string& pathForMessages,
                                           Diagnostics& diags) {
    const size_t errorsBefore = errorCount(diags);
    CsgBuilder builder(pathForMessages, diags);
    for (const Block& block : lexBlocks(text, pathForMessages, diags)) builder.addBlock(block);
    return builder.build(errorsBefore);
}

std::shared_ptr<const CsgTree> readCsgFile(const std::string& path, Diagnostics& diags) {
    const std::optional<std::string> text = readSourceFile(path, "CSG", kMaxSceneFileBytes, diags);
    return text ? readCsgText(*text, path, diags) : nullptr;
}

}  // namespace trazo
