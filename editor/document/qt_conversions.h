#pragma once
// Conversions between the model's std types and Qt's. The model speaks UTF-8
// std::string and linear RGB doubles; widgets speak QString and sRGB QColor.
#include "model/types.h"

#include <QColor>
#include <QString>
#include <QStringList>

#include <string>
#include <vector>

namespace regio::editor {

inline QString toQString(const std::string& s) { return QString::fromStdString(s); }
inline std::string toStd(const QString& s) { return s.toStdString(); }

QStringList toQStringList(const std::vector<std::string>& ids);
std::vector<std::string> toStdVector(const QStringList& ids);

// Linear [0,1] per channel <-> an sRGB-encoded colour for display and pickers.
double linearToSrgb(double c);
double srgbToLinear(double c);
QColor linearToColor(const model::Rgb& rgb);
model::Rgb colorToLinear(const QColor& colour);

// The colour an emitter is shown with: its hue at full brightness.
QColor emissionDisplayColor(const model::Rgb& emission);

// "1.25" style text for numbers in labels and status messages.
QString formatNumber(double value, int precision = 4);
QString formatVector(const model::Vec3& v, int precision = 4);

} // namespace regio::editor
