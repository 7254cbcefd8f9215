// Firefox for the server tests: Debian's firefox-esr driven by puppeteer-core over WebDriver BiDi
// (playwright-core can only drive its own patched Firefox, which would be a download). The tests
// are written against Playwright's page API; this file gives a puppeteer Firefox page the few
// Playwright calls they make, so one test file runs in both browsers.
export async function launchFirefox(executablePath) {
  const { default: puppeteer } = await import('puppeteer-core');
  const browser = await puppeteer.launch({
    browser: 'firefox', executablePath, headless: true, timeout: 60_000,
  });
  return {
    newContext: (options) => newContext(browser, options),
    close: () => browser.close(),
  };
}

async function newContext(browser, { viewport } = {}) {
  const context = await browser.createBrowserContext();
  const wrapper = {
    async newPage() {
      const page = await context.newPage();
      if (viewport) await page.setViewport(viewport);
      return playwrightLike(page, wrapper);
    },
    close: () => context.close(),
  };
  return wrapper;
}

// The puppeteer page, with Playwright's spelling of the calls the tests use.
function playwrightLike(page, context) {
  const extras = {
    context: () => context,
    waitForTimeout: (ms) => new Promise((resolve) => setTimeout(resolve, ms)),
    selectOption: (selector, value) => page.select(selector, value),
    // Playwright: (fn, arg, options); puppeteer: (fn, options, ...args).
    waitForFunction: (fn, arg, options = {}) =>
      page.waitForFunction(fn, { polling: options.polling ?? 50, timeout: options.timeout }, arg),
    locator: (selector) => ({
      focus: () => page.focus(selector),
      boundingBox: async () => (await page.$(selector)).boundingBox(),
    }),
  };
  return new Proxy(page, {
    get(target, name) {
      if (name in extras) return extras[name];
      const value = target[name];
      return typeof value === 'function' ? value.bind(target) : value;
    },
  });
}
