import { useEffect } from "react";
import { Viewport } from "./scene/Viewport";
import { startStudio } from "./studio";
import { ErrorBanner } from "./ui/ErrorBanner";
import { Legend } from "./ui/Legend";
import { MetricsPanel } from "./ui/MetricsPanel";
import { PlanPanel } from "./ui/PlanPanel";
import { Progress } from "./ui/Progress";
import { PromptBar } from "./ui/PromptBar";
import { ShareExport } from "./ui/ShareExport";
import { Timeline } from "./ui/Timeline";

export function App() {
  useEffect(() => {
    void startStudio();
  }, []);

  return (
    <div className="app">
      <header className="app__header">
        <h1 className="brand">
          Interplay <span className="muted">studio</span>
        </h1>
        <PromptBar />
      </header>
      <ErrorBanner />
      <main className="app__main">
        <div className="stage">
          <Viewport />
          <Progress />
          <Legend />
        </div>
        <aside className="sidebar">
          <PlanPanel />
          <MetricsPanel />
          <ShareExport />
        </aside>
        <Timeline />
      </main>
    </div>
  );
}
