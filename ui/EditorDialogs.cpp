#include "EditorDialogs.h"

#include "Subdivision.h"

#include <QColorDialog>
#include <QFileDialog>
#include <QInputDialog>
#include <QLabel>
#include <algorithm>

namespace pf {

QString EditorDialogs::chooseFile(QWidget* parent, FileDialog kind, const QString& current) {
    const QString sheets = tr("PaperFold sheets (*.paper)");
    switch (kind) {
    case FileDialog::Open:
        return QFileDialog::getOpenFileName(parent, tr("Open Sheet"), QString(), sheets);
    case FileDialog::Save:
        return QFileDialog::getSaveFileName(parent, tr("Save Sheet"), current, sheets);
    case FileDialog::ExportImage:
        return QFileDialog::getSaveFileName(parent, tr("Export Image"), QString(),
                                            tr("PNG images (*.png)"));
    case FileDialog::ExportMesh:
        return QFileDialog::getSaveFileName(parent, tr("Export Mesh"), QString(),
                                            tr("Meshes (*.obj *.ply *.glb)"));
    case FileDialog::PaperImage:
        return QFileDialog::getOpenFileName(parent, tr("Picture for the Paper"), QString(),
                                            tr("Images (*.png *.jpg *.jpeg *.bmp *.webp)"));
    case FileDialog::SaveRecording:
        return QFileDialog::getSaveFileName(parent, tr("Save Recording"), QString(),
                                            tr("PaperFold recordings (*.paperrec)"));
    }
    return QString();
}

void EditorDialogs::showError(QWidget* parent, const QString& message) {
    QMessageBox::critical(parent, tr("PaperFold"), message);
}

QMessageBox::StandardButton EditorDialogs::askToSave(QWidget* parent) {
    return QMessageBox::warning(parent, tr("PaperFold"),
                                tr("The sheet has unsaved changes. Save them?"),
                                QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
}

QSize EditorDialogs::chooseImageSize(QWidget* parent, const QSize& offered) {
    bool ok = false;
    const QString text = QInputDialog::getText(
        parent, tr("Export Image"), tr("Size in pixels (width x height):"), QLineEdit::Normal,
        QStringLiteral("%1x%2").arg(offered.width()).arg(offered.height()), &ok);
    if (!ok) return QSize();
    const QStringList wh = text.split(QLatin1Char('x'));
    if (wh.size() != 2) return QSize(0, 0); // unreadable: the window says what it expects
    // A negative side would make an invalid QSize, which means "cancelled".
    return QSize(std::max(0, wh[0].trimmed().toInt()), std::max(0, wh[1].trimmed().toInt()));
}

QColor EditorDialogs::chooseColor(QWidget* parent, const QColor& current) {
    return QColorDialog::getColor(current, parent, tr("Paper Colour"));
}

int EditorDialogs::chooseMeshSubdivision(QWidget* parent, int current) {
    QInputDialog dialog(parent);
    dialog.setWindowTitle(tr("Export Mesh"));
    // The range is said: the box refused 9 without a word, and a user could not tell why.
    dialog.setLabelText(tr("Subdivision level, 0 to %1: 0 writes the simulation mesh; each level "
                           "splits every triangle in four along the paper's curved surface.")
                            .arg(kMaxSubdivisionLevel));
    dialog.setInputMode(QInputDialog::IntInput);
    dialog.setIntRange(0, kMaxSubdivisionLevel);
    dialog.setIntValue(current);
    // On one line the sentence made the dialog about 750 pixels wide.
    if (auto* label = dialog.findChild<QLabel*>()) {
        label->setWordWrap(true);
        label->setMinimumWidth(320);
    }
    return dialog.exec() == QDialog::Accepted ? dialog.intValue() : -1;
}

} // namespace pf
