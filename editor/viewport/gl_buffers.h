#pragma once
// Small owners of a vertex array object and its buffers, one per kind of
// thing the viewport draws, so each can be re-uploaded on its own.
#include <QOpenGLBuffer>
#include <QOpenGLVertexArrayObject>

#include <vector>

namespace regio::editor {

// Attribute locations shared by every viewport shader.
enum VertexAttribute : unsigned { PositionAttribute = 0, NormalAttribute = 1, ColourAttribute = 2 };

// Interleaved position (+ optional normal), optional separate colour buffer.
class GlMesh {
public:
    enum class Layout {
        Position,       // xyz
        PositionNormal, // xyz nxnynz
        PositionColour, // xyz rgba (interleaved)
    };

    void create(Layout layout, bool separateColours = false);
    void destroy();
    bool isCreated() const { return m_vao.isCreated(); }
    // Replaces the vertices (floats in the layout's order).
    void upload(const std::vector<float>& vertices);
    // Replaces the separate rgba colours (one per vertex).
    void uploadColours(const std::vector<float>& colours);
    int vertexCount() const { return m_count; }
    // Draws all or a range of vertices; without a colour attribute the
    // current constant colour (glVertexAttrib4f) applies.
    void draw(unsigned mode, int first = 0, int count = -1);

private:
    QOpenGLVertexArrayObject m_vao;
    QOpenGLBuffer m_vbo{QOpenGLBuffer::VertexBuffer};
    QOpenGLBuffer m_colours{QOpenGLBuffer::VertexBuffer};
    Layout m_layout = Layout::Position;
    bool m_separateColours = false;
    int m_count = 0;
};

} // namespace regio::editor
