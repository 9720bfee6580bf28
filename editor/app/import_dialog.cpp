#include "editor/app/import_dialog.h"

#include "editor/document/qt_conversions.h"
#include "editor/document/scene_document.h"
#include "editor/viewport/viewport.h"
#include "model/io/printable.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPromise>
#include <QPushButton>
#include <QRadioButton>
#include <QThreadPool>
#include <QVBoxLayout>

namespace regio::editor {

namespace {

ImportOutcome runImport(const std::string& path, const importer::ImportOptions& options)
{
    ImportOutcome out;
    model::Result<importer::Imported> imported = importer::importModel(path, options);
    out.diagnostics = imported.takeDiagnostics();
    if (imported)
        out.imported = std::move(*imported);
    return out;
}

QString diagnosticLine(const model::Diagnostic& d)
{
    const QString where = d.pointer.empty() ? QString() : toQString(d.pointer) + QStringLiteral(": ");
    return (d.isError() ? ImportDialog::tr("error: ") : ImportDialog::tr("warning: ")) + where +
           toQString(model::printable(d.message));
}

} // namespace

ImportDialog::ImportDialog(const QString& path, bool canAddToOpenScene, QWidget* parent)
    : QDialog(parent)
    , m_path(path)
{
    setWindowTitle(tr("Import %1").arg(QFileInfo(path).fileName()));

    m_scale = new QDoubleSpinBox(this);
    m_scale->setDecimals(6);
    m_scale->setRange(1e-6, 1e6);
    m_scale->setValue(1.0);
    m_scale->setToolTip(tr("Metres per model unit: 0.001 for a model in millimetres"));
    m_up = new QComboBox(this);
    m_up->addItem(tr("Y is up"));
    m_up->addItem(tr("Z is up"));
    const importer::MergeOptions merge;
    m_angle = new QDoubleSpinBox(this);
    m_angle->setRange(0.0, 30.0);
    m_angle->setDecimals(2);
    m_angle->setSuffix(tr(" °"));
    m_angle->setValue(merge.angleDegrees);
    m_angle->setToolTip(tr("Triangles whose normals differ by at most this angle merge into one face"));
    m_distance = new QDoubleSpinBox(this);
    m_distance->setRange(0.0, 1000.0);
    m_distance->setDecimals(3);
    m_distance->setSuffix(tr(" mm"));
    m_distance->setValue(merge.distance * 1000.0);
    m_distance->setToolTip(tr("Corners this close are welded; corners this close to a plane lie in it"));
    m_regions = new QCheckBox(tr("Propose regions and BSP orders"), this);
    m_regions->setChecked(true);
    m_intoNew = new QRadioButton(tr("As a new scene"), this);
    m_intoOpen = new QRadioButton(tr("Into the open scene (one undo step)"), this);
    m_intoNew->setChecked(true);
    m_intoOpen->setEnabled(canAddToOpenScene);

    auto* form = new QFormLayout;
    form->addRow(tr("Scale:"), m_scale);
    form->addRow(tr("Up axis:"), m_up);
    form->addRow(tr("Merge angle:"), m_angle);
    form->addRow(tr("Merge distance:"), m_distance);
    form->addRow(QString(), m_regions);
    form->addRow(tr("Import:"), m_intoNew);
    form->addRow(QString(), m_intoOpen);

    m_summary = new QLabel(this);
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_messages = new QPlainTextEdit(this);
    m_messages->setReadOnly(true);
    m_messages->setMaximumBlockCount(1000);
    m_previewDocument = new SceneDocument(this);
    m_preview = new Viewport(m_previewDocument, this);
    m_preview->setMinimumSize(360, 260);

    auto* left = new QVBoxLayout;
    left->addLayout(form);
    left->addWidget(m_summary);
    left->addWidget(m_messages, 1);
    auto* columns = new QHBoxLayout;
    columns->addLayout(left, 2);
    columns->addWidget(m_preview, 3);

    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Import"));
    connect(m_buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns, 1);
    layout->addWidget(m_buttons);

    m_debounce.setSingleShot(true);
    m_debounce.setInterval(300);
    connect(&m_debounce, &QTimer::timeout, this, &ImportDialog::startImport);
    connect(&m_watcher, &QFutureWatcher<ImportOutcome>::finished, this, &ImportDialog::onFinished);
    for (QDoubleSpinBox* box : {m_scale, m_angle, m_distance})
        connect(box, &QDoubleSpinBox::valueChanged, this, &ImportDialog::scheduleImport);
    connect(m_up, &QComboBox::currentIndexChanged, this, &ImportDialog::scheduleImport);
    connect(m_regions, &QCheckBox::toggled, this, &ImportDialog::scheduleImport);
    startImport();
}

ImportDialog::~ImportDialog()
{
    // The worker owns its copies of the path and options; its result is
    // dropped. Waiting keeps the dialog from outliving it by more than one
    // import.
    m_watcher.disconnect(this);
    if (m_running)
        m_watcher.waitForFinished();
}

importer::ImportOptions ImportDialog::options() const
{
    importer::ImportOptions o;
    o.read.scale = m_scale->value();
    o.read.up = m_up->currentIndex() == 1 ? importer::UpAxis::Z : importer::UpAxis::Y;
    o.merge.angleDegrees = m_angle->value();
    o.merge.distance = m_distance->value() / 1000.0;
    o.autoRegions = m_regions->isChecked();
    return o;
}

ImportDialog::Target ImportDialog::target() const
{
    return m_intoOpen->isChecked() ? Target::OpenScene : Target::NewScene;
}

QString ImportDialog::summary() const { return m_summary->text(); }

void ImportDialog::scheduleImport()
{
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
    m_debounce.start();
}

void ImportDialog::startImport()
{
    if (m_running) {
        m_again = true;
        return;
    }
    m_running = true;
    m_again = false;
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
    m_summary->setText(tr("Importing %1…").arg(QFileInfo(m_path).fileName()));
    auto promise = std::make_shared<QPromise<ImportOutcome>>();
    m_watcher.setFuture(promise->future());
    promise->start();
    QThreadPool::globalInstance()->start([promise, path = m_path.toStdString(), options = options()] {
        promise->addResult(runImport(path, options));
        promise->finish();
    });
}

void ImportDialog::onFinished()
{
    m_running = false;
    if (m_again) {
        startImport();
        return;
    }
    m_outcome = m_watcher.result();
    showOutcome();
    emit importFinished();
}

void ImportDialog::showOutcome()
{
    QStringList lines;
    for (const model::Diagnostic& d : m_outcome.diagnostics)
        lines << diagnosticLine(d);
    m_messages->setPlainText(lines.join(QLatin1Char('\n')));
    if (!m_outcome.imported) {
        m_summary->setText(tr("The model cannot be imported (the reasons are below)."));
        m_previewDocument->reset(model::Scene{});
        m_buttons->button(QDialogButtonBox::Ok)->setEnabled(false);
        return;
    }
    const importer::ImportReport& r = m_outcome.imported->report;
    QString text = tr("%1 triangles into %2 faces; %3 objects, %4 parts (%5 closed), %6 materials, %7 emitting faces.")
                       .arg(r.merge.trianglesIn)
                       .arg(r.merge.faces)
                       .arg(r.build.objects)
                       .arg(r.build.parts)
                       .arg(r.build.closedParts)
                       .arg(r.build.materials)
                       .arg(r.build.emittingFaces);
    if (r.merge.degenerate + r.merge.duplicate + r.read.pointsAndLines > 0)
        text += QLatin1Char(' ') + tr("Left out: %1 triangles of no area, %2 repeated, %3 points or lines.")
                                       .arg(r.merge.degenerate)
                                       .arg(r.merge.duplicate)
                                       .arg(r.read.pointsAndLines);
    if (options().autoRegions)
        text += QLatin1Char(' ') + tr("Regions: %1; BSP fragments: %2 (one BSP tree: %3).")
                                       .arg(r.regions)
                                       .arg(r.fragments)
                                       .arg(r.singleTreeFragments);
    m_summary->setText(text);
    m_previewDocument->reset(m_outcome.imported->scene);
    m_preview->frameAll();
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(true);
}

} // namespace regio::editor
