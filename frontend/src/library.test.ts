// @vitest-environment node
import { describe, expect, it } from "vitest";
import type { MotionListItem, MotionPage } from "./api/types";
import { appendPage, LIBRARY_PAGE, loadPages } from "./library";

const item = (i: number): MotionListItem => ({
  id: `m${i}`, prompt: `p${i}`, persons: 1, seconds: 1, frames: 20, created_at: null, parent_id: null, edit: null, first_frame: [],
});

/** A server holding `n` motions, newest (m{n-1}) first, answering pages as the API does. */
function server(n: number) {
  const all = Array.from({ length: n }, (_, i) => item(n - 1 - i));
  const asked: [number, string | null][] = [];
  const fetchPage = async (limit: number, after: string | null): Promise<MotionPage> => {
    asked.push([limit, after]);
    const start = after ? all.findIndex((m) => m.id === after) + 1 : 0;
    const motions = all.slice(start, start + limit);
    return { motions, next: start + limit < n ? motions[motions.length - 1].id : null, total: n };
  };
  return { all, asked, fetchPage };
}

describe("My motions' pages", () => {
  it("loads the first page, and says there are more", async () => {
    const s = server(57);
    const page = await loadPages(LIBRARY_PAGE, s.fetchPage);
    expect(page.items.map((m) => m.id)).toEqual(s.all.slice(0, 20).map((m) => m.id));
    expect(page.next).toBe("m37");
    expect(page.total).toBe(57);
  });

  it("reaches every motion, none twice, page after page", async () => {
    const s = server(57);
    let { items, next } = await loadPages(LIBRARY_PAGE, s.fetchPage);
    while (next) {
      const page = await s.fetchPage(LIBRARY_PAGE, next);
      items = appendPage(items, page);
      next = page.next;
    }
    expect(items.map((m) => m.id)).toEqual(s.all.map((m) => m.id));
  });

  it("a refresh keeps as many shown as before (pages of at most 50)", async () => {
    const s = server(130);
    const page = await loadPages(120, s.fetchPage);
    expect(page.items).toHaveLength(120);
    expect(s.asked).toEqual([[50, null], [50, "m80"], [20, "m30"]]);
    const few = server(3);
    expect((await loadPages(LIBRARY_PAGE, few.fetchPage)).next).toBeNull();
  });

  it("appending a page lists a motion once", () => {
    const page: MotionPage = { motions: [item(2), item(1)], next: null, total: 3 };
    expect(appendPage([item(3), item(2)], page).map((m) => m.id)).toEqual(["m3", "m2", "m1"]);
  });
});
