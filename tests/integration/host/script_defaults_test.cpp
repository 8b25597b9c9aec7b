// The shipped scripts (resources/*.mlx) use the defaults the filters' dialogs show, so that a
// menu user and a script user get the same result. A script that differs on purpose says so in
// a comment naming the parameters and why:
//   <!-- Differs from the dialog's defaults on purpose: gain, lambda (why) -->
#include "plugin_host.h"

#include <common/meshmodel.h>

#include <gtest/gtest.h>

#include <QDir>
#include <QDomDocument>
#include <QFile>
#include <QRegularExpression>

#include <set>
#include <string>

namespace {

using hht::host::find_action;
using hht::host::plugin;

std::vector<std::string> shipped_scripts() {
  std::vector<std::string> names;
  for (const QString& file : QDir(HHT_RESOURCES_DIR).entryList({"*.mlx"}, QDir::Files, QDir::Name))
    names.push_back(file.toStdString());
  return names;
}

// The parameters named after "on purpose:" in the script's comments.
std::set<QString> deliberate_differences(const QString& text) {
  std::set<QString> names;
  const QRegularExpression comment("<!--\\s*Differs from the dialog's defaults on purpose:\\s*([^(]*)\\(");
  for (auto it = comment.globalMatch(text); it.hasNext();)
    for (const QString& name : it.next().captured(1).split(',', Qt::SkipEmptyParts)) names.insert(name.trimmed());
  return names;
}

// The dialog's default, when the script's value differs from it; empty when they agree.
QString difference(const RichParameterList& declared, const QDomElement& param) {
  const QString type = param.attribute("type"), name = param.attribute("name"), value = param.attribute("value");
  if (type == "RichFloat")
    return value.toFloat() == declared.getFloat(name) ? QString() : QString::number(double(declared.getFloat(name)));
  if (type == "RichInt") return value.toInt() == declared.getInt(name) ? QString() : QString::number(declared.getInt(name));
  if (type == "RichEnum") return value.toInt() == declared.getEnum(name) ? QString() : QString::number(declared.getEnum(name));
  if (type == "RichBool") {
    const QString dialog = declared.getBool(name) ? "true" : "false";
    return value == dialog ? QString() : dialog;
  }
  if (type == "RichSaveFile")
    return value == declared.getSaveFileName(name) ? QString() : "'" + declared.getSaveFileName(name) + "'";
  return QString();  // RichMesh: a layer index, not a default
}

class ScriptDefaults : public ::testing::TestWithParam<std::string> {};

TEST_P(ScriptDefaults, EqualTheDialogsDefaultsOrSayWhyNot) {
  QFile file(QString(HHT_RESOURCES_DIR "/") + QString::fromStdString(GetParam()));
  ASSERT_TRUE(file.open(QIODevice::ReadOnly));
  const QString text = QString::fromUtf8(file.readAll());
  QDomDocument script;
  ASSERT_TRUE(script.setContent(text));
  const std::set<QString> deliberate = deliberate_differences(text);
  std::set<QString> differing;
  const QDomNodeList filters = script.elementsByTagName("filter");
  ASSERT_GT(filters.size(), 0);
  for (int f = 0; f < filters.size(); ++f) {
    const QString name = filters.at(f).toElement().attribute("name");
    QAction* action = find_action(name);
    ASSERT_NE(action, nullptr) << name.toStdString();
    MeshDocument document;
    document.addNewMesh("", "input", true);
    RichParameterList declared;
    plugin().initParameterSet(action, document, declared);
    const QDomNodeList params = filters.at(f).toElement().elementsByTagName("Param");
    EXPECT_EQ(unsigned(params.size()), declared.size()) << name.toStdString() << ": the script must set every parameter";
    for (int p = 0; p < params.size(); ++p) {
      const QDomElement param = params.at(p).toElement();
      const QString pname = param.attribute("name");
      ASSERT_TRUE(declared.hasParameter(pname)) << name.toStdString() << " declares no " << pname.toStdString();
      const QString dialog = difference(declared, param);
      if (dialog.isEmpty()) continue;
      differing.insert(pname);
      EXPECT_TRUE(deliberate.count(pname))
          << GetParam() << ": " << pname.toStdString() << " = " << param.attribute("value").toStdString()
          << " but the dialog's default is " << dialog.toStdString()
          << " (change one of them, or say in the script why they differ)";
    }
  }
  for (const QString& name : deliberate)
    EXPECT_TRUE(differing.count(name)) << GetParam() << " says " << name.toStdString()
                                       << " differs on purpose, but it equals the dialog's default";
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.substr(0, info.param.find('.'));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Shipped, ScriptDefaults, ::testing::ValuesIn(shipped_scripts()), test_name);

}  // namespace
