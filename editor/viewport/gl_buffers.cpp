#include "editor/viewport/gl_buffers.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>

namespace regio::editor {

namespace {

int floatsPerVertex(GlMesh::Layout layout)
{
    switch (layout) {
    case GlMesh::Layout::Position: return 3;
    case GlMesh::Layout::PositionNormal: return 6;
    case GlMesh::Layout::PositionColour: return 7;
    }
    return 3;
}

} // namespace

void GlMesh::create(Layout layout, bool separateColours)
{
    m_layout = layout;
    m_separateColours = separateColours;
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    m_vao.create();
    QOpenGLVertexArrayObject::Binder bind(&m_vao);
    m_vbo.create();
    m_vbo.setUsagePattern(QOpenGLBuffer::DynamicDraw);
    m_vbo.bind();
    const int stride = floatsPerVertex(layout) * int(sizeof(float));
    gl->glEnableVertexAttribArray(PositionAttribute);
    gl->glVertexAttribPointer(PositionAttribute, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    if (layout == Layout::PositionNormal) {
        gl->glEnableVertexAttribArray(NormalAttribute);
        gl->glVertexAttribPointer(NormalAttribute, 3, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<void*>(3 * sizeof(float)));
    }
    if (layout == Layout::PositionColour) {
        gl->glEnableVertexAttribArray(ColourAttribute);
        gl->glVertexAttribPointer(ColourAttribute, 4, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<void*>(3 * sizeof(float)));
    }
    if (separateColours) {
        m_colours.create();
        m_colours.setUsagePattern(QOpenGLBuffer::DynamicDraw);
        m_colours.bind();
        gl->glEnableVertexAttribArray(ColourAttribute);
        gl->glVertexAttribPointer(ColourAttribute, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
    }
}

void GlMesh::destroy()
{
    m_vbo.destroy();
    m_colours.destroy();
    m_vao.destroy();
    m_count = 0;
}

void GlMesh::upload(const std::vector<float>& vertices)
{
    m_vbo.bind();
    m_vbo.allocate(vertices.data(), int(vertices.size() * sizeof(float)));
    m_count = int(vertices.size()) / floatsPerVertex(m_layout);
}

void GlMesh::uploadColours(const std::vector<float>& colours)
{
    if (!m_separateColours)
        return;
    m_colours.bind();
    m_colours.allocate(colours.data(), int(colours.size() * sizeof(float)));
}

void GlMesh::draw(unsigned mode, int first, int count)
{
    if (count < 0)
        count = m_count - first;
    if (count <= 0 || !m_vao.isCreated())
        return;
    QOpenGLVertexArrayObject::Binder bind(&m_vao);
    QOpenGLContext::currentContext()->extraFunctions()->glDrawArrays(mode, first, count);
}

} // namespace regio::editor
