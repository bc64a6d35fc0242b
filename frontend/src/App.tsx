import { useEffect } from "react";
import { Viewport } from "./scene/Viewport";
import { startStudio } from "./studio";
import { ErrorBanner } from "./ui/ErrorBanner";
import { Legend } from "./ui/Legend";
import { MetricsPanel } from "./ui/MetricsPanel";
import { PlanPanel } from "./ui/PlanPanel";
import { ReactorPanel } from "./ui/ReactorPanel";
import { Progress } from "./ui/Progress";
import { PromptBar } from "./ui/PromptBar";
import { ShareExport } from "./ui/ShareExport";
import { Timeline } from "./ui/Timeline";
import { Tools } from "./ui/Tools";
import { ViewButtons } from "./ui/ViewButtons";
import { PathPanel } from "./ui/PathPanel";
import { PartEditor } from "./ui/PartEditor";
import { Versions } from "./ui/Versions";
import { ThemeToggle } from "./ui/ThemeToggle";
import { EmptyState } from "./ui/EmptyState";
import { MyMotions } from "./ui/MyMotions";
import { useKeyboard } from "./ui/keyboard";
import { ShortcutButton, ShortcutSheet } from "./ui/ShortcutSheet";
import { fetchLimits } from "./api/limits";
import { useStudio } from "./store";

export function App() {
  useEffect(() => {
    void startStudio();
    // the request limits (prompt length, seconds, seed) from the API's schema
    void fetchLimits().then((limits) => useStudio.setState({ limits }));
  }, []);
  useKeyboard();

  return (
    <div className="app">
      <header className="app__header">
        <h1 className="brand" data-testid="brand">
          Interplay <span className="muted">studio</span>
        </h1>
        <PromptBar />
        <div className="header-tools">
          <Versions />
          <ThemeToggle />
          <ShortcutButton />
        </div>
      </header>
      <ErrorBanner />
      <main className="app__main">
        <div className="stage">
          <Viewport />
          <Tools />
          <ViewButtons />
          <EmptyState />
          <Progress />
          <PartEditor />
          <Legend />
        </div>
        <aside className="sidebar">
          <MyMotions />
          <ReactorPanel />
          <PathPanel />
          <PlanPanel />
          <MetricsPanel />
          <ShareExport />
        </aside>
        <Timeline />
      </main>
      <ShortcutSheet />
    </div>
  );
}
